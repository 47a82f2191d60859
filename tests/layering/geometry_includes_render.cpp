// Never built into anything: the test layering_upward_include_fails builds it and expects the
// include below to be refused, because the geometry layer sits below the render layer.
#include "geometry/bvh_node.h"
#include "render/scene_view.h"
