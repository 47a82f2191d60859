// Crops of a camera's image; see camera_crop.h.
#include "scene/camera_crop.h"

namespace candela {

std::optional<std::string> cropProblem(const CameraCrop& crop, uint32_t width, uint32_t height) {
  if (crop.width == 0 || crop.height == 0)
    return "the crop " + cropText(crop) + " is empty; expected a width and height of at least 1";
  if (uint64_t(crop.x) + crop.width > width || uint64_t(crop.y) + crop.height > height)
    return "the crop " + cropText(crop) + " reaches past the " + std::to_string(width) + " x " +
           std::to_string(height) + " image; expected x + width <= " + std::to_string(width) +
           " and y + height <= " + std::to_string(height);
  return std::nullopt;
}

std::string cropText(const CameraCrop& crop) {
  return "[" + std::to_string(crop.x) + ", " + std::to_string(crop.y) + ", " +
         std::to_string(crop.width) + ", " + std::to_string(crop.height) + "]";
}

uint32_t renderedWidth(const CameraDesc& camera) {
  return camera.crop ? camera.crop->width : camera.width;
}

uint32_t renderedHeight(const CameraDesc& camera) {
  return camera.crop ? camera.crop->height : camera.height;
}

}  // namespace candela
