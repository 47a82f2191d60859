// OBJ loading through tinyobjloader after a validation pass; see obj_loader.h.
#include "scene/read/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdio>

#include "scene/read/mtl_library.h"
#include "scene/read/obj_scanner.h"
#include "scene/scene_error.h"
#include "scene/read/text_file.h"

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

// One material per MTL material: emissive with radiance Ke where Ke is not black, else diffuse
// with colour Kd, or 0.8 where the material sets none.
std::vector<Material> mtlMaterials(const std::vector<tinyobj::material_t>& materials,
                                   const MtlLibrary& library, const std::string& label) {
  std::vector<Material> result;
  for (size_t i = 0; i < materials.size(); ++i) {
    const tinyobj::material_t& material = materials[i];
    // tinyobjloader always appends the material it was building; unnamed at the end, it is none.
    if (i + 1 == materials.size() && material.name.empty()) break;
    Material desc;
    desc.type = MaterialType::Diffuse;
    if (library.kdNames.count(material.name) != 0)
      desc.color = mtlColour(material.diffuse, "Kd", material.name, label);
    const Vec3 emission = mtlColour(material.emission, "Ke", material.name, label);
    if (!isBlack(emission)) {
      desc.type = MaterialType::Emissive;
      desc.color = Vec3(0.0f);
      desc.radiance = emission;
    }
    result.push_back(desc);
  }
  return result;
}

MeshDesc buildMesh(const tinyobj::ObjReader& reader, const MtlLibrary& library,
                   const std::string& label) {
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  MeshDesc mesh;
  mesh.positions.reserve(attrib.vertices.size() / 3);
  for (size_t i = 0; i < attrib.vertices.size() / 3; ++i)
    mesh.positions.push_back(vec3At(attrib.vertices, i));
  mesh.normals.reserve(attrib.normals.size() / 3);
  for (size_t i = 0; i < attrib.normals.size() / 3; ++i)
    mesh.normals.push_back(vec3At(attrib.normals, i));
  mesh.materials = mtlMaterials(reader.GetMaterials(), library, label);

  const auto mtlCount = static_cast<int>(mesh.materials.size());
  const auto fallback = static_cast<uint32_t>(mesh.materials.size());
  bool fallbackUsed = false;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const std::vector<tinyobj::index_t>& indices = shape.mesh.indices;
    for (size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      if (shape.mesh.num_face_vertices[face] != 3)
        throw SceneError(label + ": a polygon was not triangulated");
      MeshTriangle triangle;
      bool allNormals = true;
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
      }
      if (!allNormals) triangle.n[0] = triangle.n[1] = triangle.n[2] = -1;
      const int material = shape.mesh.material_ids[face];
      const bool known = material >= 0 && material < mtlCount;
      triangle.material = known ? static_cast<uint32_t>(material) : fallback;
      fallbackUsed = fallbackUsed || !known;
      mesh.triangles.push_back(triangle);
    }
  }
  if (fallbackUsed) mesh.materials.push_back(Material{});  // diffuse 0.8
  return mesh;
}

}  // namespace

MeshDesc loadObjFile(const std::string& path, const std::string& label) {
  std::string text, reason;
  if (!readTextFile(path, &text, &reason))
    throw SceneError("cannot open \"" + label + "\" (" + reason + ")");
  const ObjScan scan = scanObj(text, label);

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  const MtlLibrary library = readMtlLibrary(path, scan.materialLibraries);
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(scan.text, library.text, config))
    throw SceneError(label + ": " + firstLine(reader.Error()));

  MeshDesc mesh = buildMesh(reader, library, label);
  if (mesh.triangles.empty()) throw SceneError(label + ": expected at least one face, got none");
  mesh.materialFiles = library.files;
  return mesh;
}

}  // namespace candela
