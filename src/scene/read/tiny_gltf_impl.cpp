// tinygltf's implementation, compiled once into candela_scene (Debian ships it as a header).
#define TINYGLTF_IMPLEMENTATION
#include "scene/read/tiny_gltf_config.h"
