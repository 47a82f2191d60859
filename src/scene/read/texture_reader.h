// Image textures in a scene: reading each file once, and colours that may be textured.
//
// A colour field that takes a texture accepts, besides a grey or [r, g, b],
//   {"texture": "wood.png", "scale": [su, sv]}
// with the file relative to the scene file's folder and `scale` (default [1, 1]) finite and
// non-zero, or {"checkerboard": [colour0, colour1], ...}, a 2 x 2 texture of those colours. PNG,
// JPEG and WebP are 8-bit sRGB (colours) or linear (masks); EXR, PFM and .hdr are linear float. Any
// other colour field refuses a texture object (JsonValue::colour).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene/read/json_reader.h"
#include "scene/scene_desc.h"

namespace candela {

// What a texture is read for: a colour (8-bit files decoded from sRGB), values read linearly (an
// alpha mask, a normal map), or a light's profile made from an IES file.
enum class TextureUse { Color, Linear, Profile };

struct LoadedTexture {
  int32_t index = -1;     // into the scene's textures
  bool hasAlpha = false;  // the file has an alpha channel (8- or 16-bit files of 2 or 4 channels)
};

// Reads textures into a scene's list, each (file, use) once, by canonical path.
class TextureLoader {
 public:
  // `baseDir`: the scene file's folder, against which JSON names are resolved.
  TextureLoader(std::vector<std::shared_ptr<const TextureDesc>>& textures, std::string baseDir)
      : textures_(textures), baseDir_(std::move(baseDir)) {}

  const std::string& baseDir() const { return baseDir_; }
  // While it lives, names resolve against `folder` (a material library file's) instead.
  class BaseDirScope {
   public:
    BaseDirScope(TextureLoader& loader, std::string folder)
        : loader_(loader), saved_(std::move(loader.baseDir_)) {
      loader_.baseDir_ = std::move(folder);
    }
    ~BaseDirScope() { loader_.baseDir_ = std::move(saved_); }
    BaseDirScope(const BaseDirScope&) = delete;
    BaseDirScope& operator=(const BaseDirScope&) = delete;

   private:
    TextureLoader& loader_;
    std::string saved_;
  };
  // A file as the scene names it, resolved against the scene file's folder unless absolute.
  std::string resolve(const std::string& written) const;

  // The texture of the file at `path`; throws SceneError "<reason>" (naming the file as given)
  // when it cannot be read, is empty or too large, or holds a texel that is not finite and
  // non-negative.
  LoadedTexture load(const std::string& path, TextureUse use);

  // The texture of a PNG, JPEG or WebP file's bytes held in memory (a glTF file's embedded image),
  // read once per `name`, which names it in messages; throws SceneError as load() does.
  LoadedTexture loadEncoded(const std::string& bytes, const std::string& name, TextureUse use);

  // A texture made from others (`make` returns it and whether it has an alpha channel), added
  // once per (key, use): the same checks as load()'s, and its content hash set.
  LoadedTexture add(const std::string& key, TextureUse use,
                    const std::function<TextureDesc(bool* hasAlpha)>& make);

  // The light profile (render/light_profile.h) of the IES file at `path`, read once: its texture
  // and the vertical angles its values span. Throws SceneError "<file>:<line>: <reason>" (the
  // file named as given).
  struct LoadedProfile {
    int32_t index = -1;
    double first = 0, last = 180;  // degrees
  };
  LoadedProfile loadProfile(const std::string& path, const std::string& written);

  // The texture that load() returned `index` for.
  const TextureDesc& texture(int32_t index) const { return *textures_[size_t(index)]; }

 private:
  std::vector<std::shared_ptr<const TextureDesc>>& textures_;
  std::string baseDir_;
  std::map<std::pair<std::string, TextureUse>, LoadedTexture> loaded_;
  std::map<std::string, LoadedProfile> profiles_;
};

// Channel c (0-3) of texel i (row by row from the top) of `t`, linear: 8-bit colour channels
// decoded from sRGB where the texture holds colour, as a lookup reads them before filtering.
float texelValue(const TextureDesc& t, size_t i, uint32_t c);

// A colour that may be textured: returns the colour (1 for a texture: the texture alone) and sets
// `*texture` when `value` is a texture object. Errors name the JSON path.
Vec3 readTexturedColour(const JsonValue& value, TextureLoader& textures, TextureRef* texture);

// The colour of a light or an emitter: as readTexturedColour, or {"temperature": kelvin}, a black
// body's colour at luminance 1 (scene/blackbody.h).
Vec3 readLightColour(const JsonValue& value, TextureLoader& textures, TextureRef* texture);

// A material's "normal_map": a texture object, its file read linearly.
TextureRef readNormalMap(const JsonValue& value, TextureLoader& textures);

// A bump map {"texture": file, "scale": [su, sv], "height": h}: its heights read linearly (their
// luminance), and h, the height of a texel of value 1 in scene units (default 1), into *height.
TextureRef readBumpMap(const JsonValue& value, TextureLoader& textures, float* height);

// A field of values in [0, 1] given as a texture object (a material's "roughness", a mix's
// "weight"): its values read linearly, their luminance or the channel that "channel" names ("r",
// "g", "b", "a" or "luminance") into *channel; `expected` what the field takes.
TextureRef readUnitTexture(const JsonValue& value, TextureLoader& textures,
                           const std::string& expected, uint32_t* channel);

// A material's "alpha": a number in [0, 1], or a texture object whose values are read linearly
// from the channel that "channel" names, by default the image's alpha channel where it has one
// and its luminance where it has none (a grey mask).
AlphaMask readAlpha(const JsonValue& value, TextureLoader& textures);

}  // namespace candela
