// Keyframed animation: the scene at one frame of its `animation` block.
//
// Tracks interpolate linearly per component between keys (Euler angles too, so a 0 -> 360 key pair
// is one full turn) and hold the first key's value before it and the last key's value after it.
// Every frame also gets its own seed, render.seed + frame, so that noise is never frozen between
// frames of an animation or of a sequence of scene files.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene_desc.h"

namespace candela {

// The most frames an animation may have: a million frames are 11.5 hours at 24 fps.
constexpr uint32_t kMaxFrames = 1000000;

// The value of `track` at `frame` (scalars in all three components).
Vec3 evaluateTrack(const AnimTrack& track, uint32_t frame);

// The value of `track` at `time`, in frames (a fraction of the way between keys where it is not a
// whole frame).
Vec3 evaluateTrackAt(const AnimTrack& track, double time);

// `camera` with the camera tracks of `animation` applied at `frame`.
CameraDesc cameraAtFrame(const CameraDesc& camera, const AnimationDesc& animation, uint32_t frame);

// `camera` with the camera tracks of `animation` applied at `time`, in frames.
CameraDesc cameraAtTime(const CameraDesc& camera, const AnimationDesc& animation, double time);

// The times, in frames, at which a motion-blurred frame `frame` takes its camera's pose: the
// shutter's opening and closing, kShutterSegments steps between and every whole frame between
// (where a track's keys may bend the motion), increasing. Empty where the frame is not blurred:
// the shutter is an instant or no track moves the camera.
constexpr uint32_t kShutterSegments = 16;
std::vector<double> shutterTimes(const AnimationDesc& animation, uint32_t frame);

// What an open shutter blurs in `scene`, by its animation's tracks: whether they move the camera,
// and how many objects, spheres and lights they move (every light sample and light subpath finds
// what emits where it stands at its time).
struct ShutterBlur {
  bool camera = false;
  uint32_t objects = 0, spheres = 0, lights = 0;
};
ShutterBlur shutterBlur(const SceneDesc& scene);

// Light `index` of a scene, `light`, with its tracks in `animation` applied at `frame`.
LightDesc lightAtFrame(const LightDesc& light, uint32_t index, const AnimationDesc& animation,
                       uint32_t frame);
// The same at `time`, in frames (between frames: within a motion-blurred frame's exposure).
LightDesc lightAtTime(const LightDesc& light, uint32_t index, const AnimationDesc& animation,
                      double time);

// The still scene at `frame`: every track applied, render.seed + frame, no animation block, and
// the camera across the frame's exposure where it is motion-blurred (shutterCameras).
// Works for scenes without animation too (only the seed changes). A colour track on an object
// without a material of its own makes it diffuse with that colour, as a static "color" would.
SceneDesc sceneAtFrame(const SceneDesc& scene, uint32_t frame);

}  // namespace candela
