"""The pixel filter (render "filter") of a candela scene as Mitsuba 3's reconstruction filter, for
the reference tools: tools/mitsuba_lights.py maps it (for a scene with any of the lights, an
environment map, or neither).

Mapping: candela's "tent" of radius r is Mitsuba's `tent` of the same radius, its "gaussian" of
standard deviation s Mitsuba's `gaussian` of the same `stddev` (both cut off at 4 s; Mitsuba
also subtracts the weight at 4 s, 0.034% of the peak), "box" its `box`. Mitsuba splats each sample
into every pixel within the filter's reach and divides by the weights; candela draws each pixel's
samples from the filter: the same mean. The film samples the border (`sample_border`) so that the
pixels at the image's edges see the plane beyond it, as candela's do.
"""

DEFAULT_WIDTH = {'tent': 1.0, 'gaussian': 0.5}


def take_filter(scene):
    """Mitsuba's reconstruction filter for the "filter" of `scene` (a dict, read as JSON), which it
    takes out of the scene, since the shared harness does not know it; None where there is none."""
    spec = scene.get('render', {}).pop('filter', None)
    if spec is None:
        return None
    if isinstance(spec, str):
        spec = {'type': spec}
    kind = spec['type']
    if kind == 'tent':
        return {'type': 'tent', 'radius': spec.get('radius', DEFAULT_WIDTH['tent'])}
    if kind == 'gaussian':
        return {'type': 'gaussian', 'stddev': spec.get('stddev', DEFAULT_WIDTH['gaussian'])}
    return {'type': 'box'}


def apply_filter(scene_dict, rfilter):
    """Puts `rfilter` (take_filter's) on the film of the harness's scene dict."""
    if rfilter is not None:
        scene_dict['sensor']['film'].update(rfilter=rfilter, sample_border=True)
