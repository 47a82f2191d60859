// OBJ loading through tinyobjloader after a validation pass; see obj_loader.h.
#include "scene/read/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <unordered_set>

#include "core/constants.h"
#include "core/texture.h"
#include "render/material_prepare.h"
#include "scene/read/did_you_mean.h"
#include "scene/read/mtl_library.h"
#include "scene/read/normal_map_guess.h"
#include "scene/read/obj_scanner.h"
#include "scene/read/resolve_path.h"
#include "scene/read/texel_check.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

Vec3 vec3At(const std::vector<tinyobj::real_t>& values, size_t index) {
  return {values[3 * index], values[3 * index + 1], values[3 * index + 2]};
}

// A finite, non-negative colour of an MTL material, or one error naming the material and key.
Vec3 mtlColour(const tinyobj::real_t* values, const char* key, const std::string& material,
               const std::string& label) {
  const Vec3 colour(values[0], values[1], values[2]);
  for (int c = 0; c < 3; ++c)
    if (!(colour[c] >= 0 && std::isfinite(colour[c])))
      throw SceneError(label + ": material \"" + material + "\": expected a finite, non-negative " +
                       key + ", got " + formatNumber(colour.x) + " " + formatNumber(colour.y) +
                       " " + formatNumber(colour.z));
  return colour;
}

[[noreturn]] void failAt(const MtlStatement& statement, const std::string& reason) {
  throw SceneError(statement.file + ":" + std::to_string(statement.line) + ": " + reason);
}

// Whether `word` is a number, all of it (strtof's), into *value.
bool readNumber(const std::string& word, float* value) {
  char* end = nullptr;
  *value = std::strtof(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

// A number in [0, 1] from `d` or `Tr` (its only argument).
float unitNumber(const MtlStatement& statement, const char* keyword) {
  const std::string& text = statement.arguments;
  float value = 0.0f;
  if (!readNumber(text, &value) || !(value >= 0.0f && value <= 1.0f))
    failAt(statement, std::string("expected ") + keyword + " between 0 and 1, got \"" + text +
                          "\"");
  return value;
}

// What `in` has left of its line, without the blanks it starts with.
std::string restOfLine(std::istringstream& in) {
  std::string remaining;
  std::getline(in, remaining);
  const size_t first = remaining.find_first_not_of(" \t");
  return first == std::string::npos ? "" : remaining.substr(first);
}

// A texture statement "map_Kd [-s u v [w]] file": its texture, loaded for `use`. The -s scale
// and -o offset are honoured (w ignored), and -clamp on (the edge texels beyond [0, 1]); with
// `bumpMultiplier`, a bump map's, so is -bm (into it); with `channel`, a scalar texture's, so is
// -imfchan (r, g, b, m for the alpha channel, l for the luminance: Material::roughnessChannel's
// values, into it); other options are refused.
TextureRef mtlTexture(const MtlStatement& statement, const char* keyword, TextureUse use,
                      TextureLoader& textures, bool* hasAlpha, float* bumpMultiplier = nullptr,
                      uint32_t* channel = nullptr) {
  TextureRef ref;
  std::string rest = statement.arguments;
  while (!rest.empty() && rest[0] == '-') {
    std::istringstream in(rest);
    std::string option;
    in >> option;
    if (option == "-imfchan" && channel) {
      std::string word;
      in >> word;
      const std::string channels = "rgbm";
      if (word.size() == 1 && channels.find(word[0]) != std::string::npos)
        *channel = uint32_t(channels.find(word[0]));
      else if (word == "l")
        *channel = kLuminanceChannel;
      else
        failAt(statement,
               std::string(keyword) + " -imfchan: expected r, g, b, m or l, got \"" + word + "\"");
      rest = restOfLine(in);
      continue;
    }
    if (option == "-bm" && bumpMultiplier) {
      std::string word;
      in >> word;
      float value = 0.0f;
      if (!readNumber(word, &value) || !(std::isfinite(value) && value != 0.0f))
        failAt(statement, std::string(keyword) +
                              " -bm: expected a finite, non-zero multiplier, got \"" + word + "\"");
      *bumpMultiplier = value;
      rest = restOfLine(in);
      continue;
    }
    if (option == "-clamp") {
      std::string word;
      in >> word;
      if (word != "on" && word != "off")
        failAt(statement,
               std::string(keyword) + " -clamp: expected on or off, got \"" + word + "\"");
      ref.wrapS = ref.wrapT = word == "on" ? TextureWrap::Clamp : TextureWrap::Repeat;
      rest = restOfLine(in);
      continue;
    }
    if (option != "-s" && option != "-o")
      failAt(statement, std::string(keyword) + " option \"" + option +
                            "\" is not supported (only -s, -o" +
                            (bumpMultiplier ? ", -clamp and -bm)"
                             : channel      ? ", -clamp and -imfchan)"
                                            : " and -clamp)"));
    // -s u [v [w]] scales (v defaults to u), -o u [v [w]] offsets (v defaults to 0); w, the third
    // texture coordinate's, is read and not used.
    const bool scaling = option == "-s";
    float values[3] = {0.0f, 0.0f, 0.0f};
    int count = 0;
    for (std::string word; count < 3 && in >> word; ++count) {
      float value = 0.0f;
      if (!readNumber(word, &value)) {
        in.seekg(-std::streamoff(word.size()), std::ios::cur);  // the file name
        break;
      }
      if (!(std::isfinite(value) && (value != 0.0f || !scaling)))
        failAt(statement, std::string(keyword) + " " + option + ": expected finite" +
                              (scaling ? ", non-zero scales" : " offsets") + ", got \"" + word +
                              "\"");
      values[count] = value;
    }
    if (count == 0)
      failAt(statement, std::string(keyword) + " " + option + ": expected " +
                            (scaling ? "a scale" : "an offset"));
    if (scaling) {
      ref.scaleU = values[0];
      ref.scaleV = count > 1 ? values[1] : values[0];
    } else {
      ref.offsetU = values[0];
      ref.offsetV = values[1];
    }
    rest = restOfLine(in);
  }
  if (rest.empty()) failAt(statement, std::string("expected a file name after ") + keyword);
  const std::string path = resolvePath(rest, statement.folder);
  try {
    const LoadedTexture loaded = textures.load(path, use);
    ref.index = loaded.index;
    if (hasAlpha) *hasAlpha = loaded.hasAlpha;
  } catch (const SceneError& e) {
    failAt(statement, e.what());
  }
  return ref;
}

// The roughness that stands for a Phong exponent Ns: Walter et al. 2007's equivalent microfacet
// alpha sqrt(2 / (Ns + 2)), as roughness = sqrt(alpha).
float roughnessOfPhongExponent(float ns) {
  return std::min(1.0f, std::sqrt(std::sqrt(2.0f / (std::max(ns, 0.0f) + 2.0f))));
}

// The roughness of a glossy MTL material's Phong exponent Ns (roughnessOfPhongExponent).
float mtlPhongRoughness(const tinyobj::material_t& material, const std::string& label) {
  if (!(std::isfinite(material.shininess) && material.shininess >= 0.0f))
    throw SceneError(label + ": material \"" + material.name +
                     "\": expected a finite, non-negative Ns, got " +
                     formatNumber(material.shininess));
  return roughnessOfPhongExponent(material.shininess);
}

// A metal's anisotropy (`aniso`, in [0, 1]) and its rotation (`anisor`, a fraction of a full turn
// counter-clockwise, as Blender's Anisotropic Rotation), read as the JSON anisotropy's.
void readMtlAnisotropy(const MtlTextures& s, Material* desc) {
  if (s.aniso) desc->anisotropy = unitNumber(*s.aniso, "aniso");
  if (s.anisor && desc->anisotropy > 0.0f)
    desc->anisotropyRotation = unitNumber(*s.anisor, "anisor") * 2.0f * kPi;
}

// The PBR extension's metalness m (`Pm`, or `map_Pm` in its place) on a material with a diffuse
// colour, `desc` as it is without: where m is 1 the surface is a conductor of that colour (the
// metallic workflow of glTF and Blender, whose base colour is a metal's reflectance), rough as
// the material says (Pr, map_Pr or Ns) and anisotropic by aniso and anisor; where 0 it stays
// `desc`; between, a mix of the two, its parts appended to `parts`. Normal and bump maps shade
// both parts, and the alpha masks the mix.
void applyMetalness(const MtlTextures& s, const tinyobj::material_t& material,
                    const std::string& label, TextureLoader& textures, Material* desc,
                    std::vector<Material>* parts) {
  Material metal;
  metal.type = MaterialType::Conductor;
  metal.color = desc->color;
  metal.colorTexture = desc->colorTexture;
  metal.normalMap = desc->normalMap;
  metal.bumpHeight = desc->bumpHeight;
  if (desc->type == MaterialType::Plastic) {  // its roughness read as a glossy material's
    metal.roughness = desc->roughness;
    metal.roughnessTexture = desc->roughnessTexture;
    metal.roughnessChannel = desc->roughnessChannel;
  } else {
    metal.roughness = s.pr ? 0.0f : mtlPhongRoughness(material, label);
    if (s.pr) metal.roughness = unitNumber(*s.pr, "Pr");
    if (s.mapPr)
      metal.roughnessTexture = mtlTexture(*s.mapPr, "map_Pr", TextureUse::Linear, textures, nullptr,
                                          nullptr, &metal.roughnessChannel);
  }
  readMtlAnisotropy(s, &metal);
  prepareMaterial(&metal);
  Material mix;
  mix.type = MaterialType::Mix;
  if (s.mapPm) {
    mix.mixWeightTexture = mtlTexture(*s.mapPm, "map_Pm", TextureUse::Linear, textures, nullptr,
                                      nullptr, &mix.mixWeightChannel);
  } else {
    mix.mixWeight = unitNumber(*s.pm, "Pm");
    if (mix.mixWeight == 0.0f) return;
    if (mix.mixWeight == 1.0f) {
      metal.alpha = desc->alpha;
      *desc = metal;
      return;
    }
  }
  mix.alpha = desc->alpha;
  desc->alpha = AlphaMask();
  mix.mixParts[0] = uint32_t(parts->size());
  parts->push_back(*desc);
  mix.mixParts[1] = uint32_t(parts->size());
  parts->push_back(metal);
  *desc = mix;
}

// The PBR extension's clear coat, `Pc` (its weight) and `Pcr` (its roughness), and its sheen,
// `Ps` (a grey of that value, roughness 0.5), as the layers of `desc` (render/bsdf_coat.h,
// render/bsdf_sheen.h), or of both its parts where it is a mix (Pm); an emissive material takes
// none, with a warning naming the line.
void applyMtlLayers(const MtlTextures& s, const std::string& name, Material* desc,
                    std::vector<Material>* parts, std::vector<std::string>* warnings) {
  const float weight = s.pc ? unitNumber(*s.pc, "Pc") : 0.0f;
  const float roughness = s.pcr ? unitNumber(*s.pcr, "Pcr") : 0.0f;
  const float sheen = s.ps ? unitNumber(*s.ps, "Ps") : 0.0f;
  if (weight == 0.0f && sheen == 0.0f) return;
  if (desc->type == MaterialType::Emissive) {
    const MtlStatement& layer = weight > 0.0f ? *s.pc : *s.ps;
    warnings->push_back(layer.file + ":" + std::to_string(layer.line) + ": \"" +
                        (weight > 0.0f ? "Pc" : "Ps") + "\" not used: material \"" + name +
                        "\" is emissive, and an emissive material reflects nothing");
    return;
  }
  const auto layer = [&](Material* m) {
    m->coatWeight = weight;
    m->coatRoughness = roughness;
    m->sheenColor = Vec3(sheen);
    prepareMaterial(m);
  };
  if (desc->type != MaterialType::Mix) return layer(desc);
  for (const uint32_t part : desc->mixParts) layer(&(*parts)[part]);
}

// Ke (times map_Ke) as the emission of `desc`, a material that reflects too (a mix's own where
// Pm made one). An emitting surface is sampled over all its area, so its alpha (set by one of
// s's statements) is not used.
void addMtlEmission(const MtlTextures* s, const Vec3& emission, const TextureRef& texture,
                    Material* desc, std::vector<std::string>* warnings) {
  desc->radiance = emission;
  desc->emissionTexture = texture;
  if (isMasked(desc->alpha)) {
    const MtlStatement& alpha = s->mapD ? *s->mapD : s->d ? *s->d : *s->tr;
    warnings->push_back(alpha.file + ":" + std::to_string(alpha.line) +
                        ": the alpha is not used: the material emits (Ke), and an emitting "
                        "surface is a light over all its area");
  }
  desc->alpha = AlphaMask();
}

// One material per MTL material (docs/scene-format.md, MTL materials): emissive with radiance Ke
// (times map_Ke, Ke 1 where only map_Ke is given) where either is set and neither a Kd that is
// not black, nor map_Kd, nor Ks is (with one, as below and with that emission); else with a Ks that
// is not black a plastic (colour Kd or map_Kd, index Ni) or, without a diffuse colour, a conductor
// of reflectance Ks, rough as Ns says; else diffuse with colour Kd (0.8 where the material sets
// none), times map_Kd when it has one. A glossy material's roughness is Pr where given, or a
// texture of them (map_Pr). Alpha is d (or 1 - Tr; d wins when both are given) times map_d's alpha
// channel (or, for an image without one, its first channel). `norm` is a normal map, and where
// there is none `bump` (or `map_Bump`) a bump map of heights, -bm its height.
std::vector<Material> mtlMaterials(const std::vector<tinyobj::material_t>& materials,
                                   const MtlLibrary& library, const std::string& label,
                                   TextureLoader& textures, std::vector<Material>* mixParts,
                                   std::vector<std::string>* warnings) {
  std::vector<Material> result;
  for (size_t i = 0; i < materials.size(); ++i) {
    const tinyobj::material_t& material = materials[i];
    // tinyobjloader always appends the material it was building; unnamed at the end, it is none.
    if (i + 1 == materials.size() && material.name.empty()) break;
    Material desc;
    desc.type = MaterialType::Diffuse;
    const bool hasKd = library.kdNames.count(material.name) != 0;
    if (hasKd) desc.color = mtlColour(material.diffuse, "Kd", material.name, label);
    Vec3 emission = mtlColour(material.emission, "Ke", material.name, label);
    TextureRef emissionTexture;
    const auto found = library.statements.find(material.name);
    if (found != library.statements.end() && found->second.mapKe) {
      emissionTexture =
          mtlTexture(*found->second.mapKe, "map_Ke", TextureUse::Color, textures, nullptr);
      if (isBlack(emission)) emission = Vec3(1.0f);  // map_Ke alone: the texture is the radiance
      const std::string beyond =
          firstTexelBeyondFloat(textures.texture(emissionTexture.index), emission);
      if (!beyond.empty())
        failAt(*found->second.mapKe, "map_Ke: the texture's " + beyond + " times Ke " +
                                         formatVec3(emission) +
                                         " is beyond single precision; expected a smaller Ke");
    }
    const Vec3 specular = mtlColour(material.specular, "Ks", material.name, label);
    // An emitter that also sets how it reflects (Blender writes Kd, Ks and Ke for a material with
    // an emission) reflects as it says and emits; one with Ke alone only emits.
    const bool reflects = (hasKd && !isBlack(desc.color)) || !isBlack(specular) ||
                          (found != library.statements.end() && found->second.mapKd);
    if (!isBlack(emission) && !reflects) {
      desc.type = MaterialType::Emissive;
      desc.color = Vec3(0.0f);
      desc.radiance = emission;
      desc.emissionTexture = emissionTexture;
    }
    if (found != library.statements.end() && desc.type == MaterialType::Diffuse) {
      const MtlTextures& s = found->second;
      if (s.mapKd) {
        desc.colorTexture = mtlTexture(*s.mapKd, "map_Kd", TextureUse::Color, textures, nullptr);
        if (!hasKd) desc.color = Vec3(1.0f);
      }
      if (s.d)
        desc.alpha.constant = unitNumber(*s.d, "d");
      else if (s.tr)
        desc.alpha.constant = 1.0f - unitNumber(*s.tr, "Tr");
      if (s.mapD) {
        bool hasAlpha = false;
        desc.alpha.texture = mtlTexture(*s.mapD, "map_d", TextureUse::Linear, textures, &hasAlpha);
        desc.alpha.channel = hasAlpha ? 3 : 0;
      }
      if (s.norm) {
        desc.normalMap = mtlTexture(*s.norm, "norm", TextureUse::Linear, textures, nullptr);
      } else if (s.bump) {
        desc.bumpHeight = 1.0f;
        desc.normalMap = mtlTexture(*s.bump, s.bumpKeyword.c_str(), TextureUse::Linear, textures,
                                    nullptr, &desc.bumpHeight);
        const TextureDesc& map = textures.texture(desc.normalMap.index);
        if (holdsUnitNormals(map)) {
          warnings->push_back(
              s.bump->file + ":" + std::to_string(s.bump->line) + ": \"" + s.bumpKeyword +
              "\" names " + std::filesystem::path(map.file).filename().string() +
              ", whose texels are unit normals: read as a tangent-space normal map (as Blender "
              "writes them there)" +
              (desc.bumpHeight != 1.0f ? ", its -bm not used" : "") +
              "; write it as \"norm\" to say so");
          desc.bumpHeight = 0.0f;
        }
      }
    }
    if (desc.type == MaterialType::Diffuse && !isBlack(specular)) {
      desc.roughness = mtlPhongRoughness(material, label);
      if (found != library.statements.end()) {
        const MtlTextures& s = found->second;
        if (s.pr) desc.roughness = unitNumber(*s.pr, "Pr");
        if (s.mapPr)
          desc.roughnessTexture = mtlTexture(*s.mapPr, "map_Pr", TextureUse::Linear, textures,
                                             nullptr, nullptr, &desc.roughnessChannel);
      }
      if (isBlack(desc.color) && desc.colorTexture.index < 0) {
        desc.type = MaterialType::Conductor;
        desc.color = specular;
        if (found != library.statements.end()) readMtlAnisotropy(found->second, &desc);
      } else {
        if (found != library.statements.end() && found->second.aniso && !found->second.pm &&
            !found->second.mapPm) {
          const MtlStatement& aniso = *found->second.aniso;
          warnings->push_back(aniso.file + ":" + std::to_string(aniso.line) +
                              ": \"aniso\" not used: material \"" + material.name +
                              "\" has a diffuse colour, so it is a plastic, whose coat is "
                              "isotropic");
        }
        desc.type = MaterialType::Plastic;
        // tinyobjloader's default Ni is 1, which exporters also write for "not set".
        if (std::isfinite(material.ior) && material.ior > 1.0f) desc.ior = material.ior;
        prepareMaterial(&desc);
      }
    }
    const bool diffuseColour =
        desc.type == MaterialType::Diffuse || desc.type == MaterialType::Plastic;
    if (found != library.statements.end() && diffuseColour &&
        (found->second.pm || found->second.mapPm))
      applyMetalness(found->second, material, label, textures, &desc, mixParts);
    if (found != library.statements.end())
      applyMtlLayers(found->second, material.name, &desc, mixParts, warnings);
    if (!isBlack(emission) && reflects)
      addMtlEmission(found != library.statements.end() ? &found->second : nullptr, emission,
                     emissionTexture, &desc, warnings);
    result.push_back(desc);
  }
  return result;
}

MeshDesc buildMesh(const tinyobj::ObjReader& reader, const MtlLibrary& library,
                   const std::string& label, TextureLoader& textures, const std::string& group) {
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  MeshDesc mesh;
  mesh.positions.reserve(attrib.vertices.size() / 3);
  for (size_t i = 0; i < attrib.vertices.size() / 3; ++i)
    mesh.positions.push_back(vec3At(attrib.vertices, i));
  mesh.normals.reserve(attrib.normals.size() / 3);
  for (size_t i = 0; i < attrib.normals.size() / 3; ++i)
    mesh.normals.push_back(vec3At(attrib.normals, i));
  // Vertex colours where every vertex has one (tinyobjloader keeps none otherwise): display
  // colours, sRGB-encoded as a PLY's.
  if (attrib.colors.size() == attrib.vertices.size()) {
    mesh.colors.reserve(attrib.colors.size() / 3);
    for (size_t i = 0; i < attrib.colors.size() / 3; ++i) {
      const Vec3 c = vec3At(attrib.colors, i);
      mesh.colors.push_back(
          Vec3(srgbToLinearValue(c.x), srgbToLinearValue(c.y), srgbToLinearValue(c.z)));
    }
  }
  mesh.uvs.reserve(attrib.texcoords.size() / 2);
  for (size_t i = 0; i < attrib.texcoords.size() / 2; ++i)
    mesh.uvs.push_back(Vec2(attrib.texcoords[2 * i], attrib.texcoords[2 * i + 1]));
  mesh.materials =
      mtlMaterials(reader.GetMaterials(), library, label, textures, &mesh.mixParts, &mesh.warnings);

  const auto mtlCount = static_cast<int>(mesh.materials.size());
  const auto fallback = static_cast<uint32_t>(mesh.materials.size());
  bool fallbackUsed = false;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    if (!group.empty() && shape.name != group) continue;
    const std::vector<tinyobj::index_t>& indices = shape.mesh.indices;
    for (size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      if (shape.mesh.num_face_vertices[face] != 3)
        throw SceneError(label + ": a polygon was not triangulated");
      MeshTriangle triangle;
      bool allNormals = true, allUvs = true;
      for (int corner = 0; corner < 3; ++corner) {
        const tinyobj::index_t& index = indices[3 * face + corner];
        // The scanner checked every index; this guards against a tinyobjloader surprise.
        if (index.vertex_index < 0 ||
            static_cast<size_t>(index.vertex_index) >= mesh.positions.size())
          throw SceneError(label + ": a face refers to a vertex that does not exist");
        triangle.v[corner] = static_cast<uint32_t>(index.vertex_index);
        triangle.n[corner] = index.normal_index;
        allNormals = allNormals && index.normal_index >= 0 &&
                     static_cast<size_t>(index.normal_index) < mesh.normals.size();
        triangle.t[corner] = index.texcoord_index;
        allUvs = allUvs && index.texcoord_index >= 0 &&
                 static_cast<size_t>(index.texcoord_index) < mesh.uvs.size();
      }
      if (!allNormals) triangle.n[0] = triangle.n[1] = triangle.n[2] = -1;
      if (!allUvs) triangle.t[0] = triangle.t[1] = triangle.t[2] = -1;
      const int material = shape.mesh.material_ids[face];
      const bool known = material >= 0 && material < mtlCount;
      triangle.material = known ? static_cast<uint32_t>(material) : fallback;
      fallbackUsed = fallbackUsed || !known;
      mesh.triangles.push_back(triangle);
    }
  }
  if (fallbackUsed) {  // diffuse 0.8, or 1 under vertex colours, which then are its colour
    mesh.materials.push_back(Material{});
    if (!mesh.colors.empty()) mesh.materials.back().color = Vec3(1.0f);
  }
  return mesh;
}

// Keeps of the mesh's positions (with their colours), normals and uvs those its triangles use, in
// their order, and renumbers the triangles' corners: a group's mesh holds its own vertices alone,
// which its bounds and vertex count then describe.
void keepUsedVertices(MeshDesc* mesh) {
  constexpr uint32_t kUnused = 0xffffffffu;
  std::vector<uint32_t> position(mesh->positions.size(), kUnused);
  std::vector<uint32_t> normal(mesh->normals.size(), kUnused), uv(mesh->uvs.size(), kUnused);
  MeshDesc kept;
  // A corner's optional normal or uv (-1: none): the kept one's index, kept at its first use.
  const auto renumber = [](int32_t* index, std::vector<uint32_t>& map, const auto& from, auto* to) {
    if (*index < 0) return;
    uint32_t& slot = map[size_t(*index)];
    if (slot == kUnused) {
      slot = uint32_t(to->size());
      to->push_back(from[size_t(*index)]);
    }
    *index = int32_t(slot);
  };
  const bool coloured = !mesh->colors.empty();
  for (MeshTriangle& triangle : mesh->triangles)
    for (int corner = 0; corner < 3; ++corner) {
      uint32_t& v = position[triangle.v[corner]];
      if (v == kUnused) {
        v = uint32_t(kept.positions.size());
        kept.positions.push_back(mesh->positions[triangle.v[corner]]);
        if (coloured) kept.colors.push_back(mesh->colors[triangle.v[corner]]);
      }
      triangle.v[corner] = v;
      renumber(&triangle.n[corner], normal, mesh->normals, &kept.normals);
      renumber(&triangle.t[corner], uv, mesh->uvs, &kept.uvs);
    }
  mesh->positions = std::move(kept.positions);
  mesh->colors = std::move(kept.colors);
  mesh->normals = std::move(kept.normals);
  mesh->uvs = std::move(kept.uvs);
}

// The name `group` among the file's groups with faces (tinyobjloader's shapes, named by their `g`
// or `o`), else ObjGroupError naming them and the likely one meant.
void checkGroup(const tinyobj::ObjReader& reader, const std::string& group) {
  std::vector<std::string> names;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    if (shape.name == group) return;
    if (!shape.name.empty() && std::find(names.begin(), names.end(), shape.name) == names.end())
      names.push_back(shape.name);
  }
  if (names.empty())
    throw ObjGroupError(
        "no face of the file lies in a named group or object (\"g\" or \"o\"), so "
        "none in \"" +
        group + "\"");
  const std::string close = closestMatch(group, names);
  throw ObjGroupError("the file has no faces in a group or object \"" + group + "\"" +
                      (close.empty() ? "" : " (did you mean \"" + close + "\"?)") +
                      "; those with faces: " + quotedNames(names));
}

// Of the libraries that cannot be read, and of the materials that no library defines, this many
// are named one by one, the rest counted in one line.
constexpr size_t kWarningsNamed = 5;

// What the OBJ file's MTL files leave undefined: a library that cannot be read, or else a material
// that no library defines (where the file names any library: `usemtl` alone is common in files
// without materials). Their faces are diffuse 0.8 (docs/scene-format.md, MTL materials).
std::vector<std::string> materialWarnings(const ObjScan& scan, const MtlLibrary& library,
                                          const std::vector<tinyobj::material_t>& materials,
                                          const std::string& label) {
  std::vector<std::string> warnings;
  size_t count = 0;
  const auto warn = [&](size_t line, const std::string& what) {
    if (++count <= kWarningsNamed)
      warnings.push_back(label + ":" + std::to_string(line) + ": " + what);
  };
  const auto countRest = [&](const char* what) {
    if (count > kWarningsNamed)
      warnings.push_back(label + ": " + std::to_string(count - kWarningsNamed) + " more " + what +
                         "; diffuse 0.8 in their stead");
  };
  for (const MtlLibrary::Unread& unread : library.unread)
    warn(unread.library.line, "cannot read the material library \"" + unread.library.name + "\" (" +
                                  unread.why + "); the materials it would define are diffuse 0.8");
  countRest("material libraries that cannot be read");
  if (count > 0 || scan.materialLibraries.empty()) return warnings;
  std::unordered_set<std::string> defined;
  for (const tinyobj::material_t& m : materials) defined.insert(m.name);
  for (const NamedAtLine& use : scan.materialUses)
    if (defined.count(use.name) == 0)
      warn(use.line, "no material library defines \"" + use.name + "\"; its faces are diffuse 0.8");
  countRest("materials that no material library defines");
  return warnings;
}

// The bump maps that the MTL files name beside a normal map (`norm`), which candela reads
// instead (docs/scene-format.md, MTL materials): one left out silently would look like a
// mistake.
std::vector<std::string> bumpWarnings(const MtlLibrary& library) {
  std::vector<std::string> warnings;
  for (const auto& [name, statements] : library.statements) {
    if (!statements.bump || !statements.norm) continue;
    const MtlStatement& s = *statements.bump;
    warnings.push_back(s.file + ":" + std::to_string(s.line) + ": \"" + statements.bumpKeyword +
                       "\" is not read: material \"" + name +
                       "\" has a normal map (\"norm\"), which it renders with instead");
  }
  return warnings;
}

}  // namespace

MeshDesc loadObjFile(const std::string& path, const std::string& label, TextureLoader& textures,
                     const std::string& group) {
  std::string text, reason;
  if (!readTextFile(path, &text, &reason))
    throw SceneError("cannot open \"" + label + "\" (" + reason + ")");
  const ObjScan scan = scanObj(text, label);

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  const MtlLibrary library = readMtlLibrary(path, label, scan.materialLibraries);
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(scan.text, library.text, config))
    throw SceneError(label + ": " + firstLine(reader.Error()));

  if (!group.empty()) checkGroup(reader, group);
  MeshDesc mesh = buildMesh(reader, library, label, textures, group);
  if (mesh.triangles.empty()) throw SceneError(label + ": expected at least one face, got none");
  if (!group.empty()) keepUsedVertices(&mesh);
  mesh.materialFiles = library.files;
  std::vector<std::string> warnings = materialWarnings(scan, library, reader.GetMaterials(), label);
  for (std::string& warning : bumpWarnings(library)) warnings.push_back(std::move(warning));
  if (scan.colouredVertices > 0 && scan.colouredVertices < scan.vertices)
    warnings.push_back(label + ":" + std::to_string(scan.firstUncolouredLine) +
                       ": a vertex without a colour, where " +
                       std::to_string(scan.colouredVertices) + " of the file's " +
                       std::to_string(scan.vertices) + " have one: no vertex colours are used");
  // Then those of the materials (normal maps written as bump maps).
  warnings.insert(warnings.end(), mesh.warnings.begin(), mesh.warnings.end());
  mesh.warnings = std::move(warnings);
  return mesh;
}

}  // namespace candela
