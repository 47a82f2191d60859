// OBJ loading: the variants real files come in (CRLF, relative indices, polygons, with and without
// normals and MTL files) and malformed files, which must fail with their line, never crash.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/read/obj_loader.h"
#include "scene/read/polygon_triangulation.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::TempDir;

class ObjLoader : public ::testing::Test {
 protected:
  MeshDesc load(const std::string& text, const std::string& mtl = "") const {
    if (!mtl.empty()) dir.write("m.mtl", mtl);
    return loadObjFile(dir.write("m.obj", text), "m.obj", loader);
  }
  // The message of the SceneError that loading `text` throws, or a note that it threw none.
  std::string error(const std::string& text) const {
    try {
      load(text);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(no SceneError)";
  }

  TempDir dir;
  mutable std::vector<std::shared_ptr<const TextureDesc>> textures;
  mutable TextureLoader loader{textures, "."};
};

void expectTriangle(const MeshTriangle& t, uint32_t a, uint32_t b, uint32_t c) {
  EXPECT_EQ(t.v[0], a);
  EXPECT_EQ(t.v[1], b);
  EXPECT_EQ(t.v[2], c);
}

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST_F(ObjLoader, TriangleWithoutNormalsUsesFaceNormalAndDefaultMaterial) {
  const MeshDesc mesh = load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_FLOAT_EQ(mesh.positions[1].x, 1);
  EXPECT_TRUE(mesh.normals.empty());
  ASSERT_EQ(mesh.triangles.size(), 1u);
  expectTriangle(mesh.triangles[0], 0, 1, 2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(mesh.triangles[0].n[i], -1);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.triangles[0].material, 0u);
  EXPECT_EQ(mesh.materials[0].type, MaterialType::Diffuse);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.y, 0.8f);
}

TEST_F(ObjLoader, QuadBecomesTwoTrianglesWithTheSameWinding) {
  const MeshDesc mesh = load(std::string(kSquare) + "f 1 2 3 4\n");
  ASSERT_EQ(mesh.triangles.size(), 2u);
  for (const MeshTriangle& t : mesh.triangles) {
    const Vec3 n = cross(mesh.positions[t.v[1]] - mesh.positions[t.v[0]],
                         mesh.positions[t.v[2]] - mesh.positions[t.v[0]]);
    EXPECT_GT(n.z, 0) << "counter-clockwise seen from +z, as written";
  }
}

TEST_F(ObjLoader, PentagonBecomesThreeTriangles) {
  const MeshDesc mesh = load("v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 2 0\nv -0.5 1 0\nf 1 2 3 4 5\n");
  EXPECT_EQ(mesh.triangles.size(), 3u);
}

// Corners on the unit circle; every `dent`-th one (if any) pulled in to make the face concave.
std::string circleFace(size_t corners, size_t dent) {
  std::string text;
  for (size_t i = 0; i < corners; ++i) {
    const double angle = 2 * 3.14159265358979323846 * double(i) / double(corners);
    const double r = dent != 0 && i % dent == 0 ? 0.5 : 1.0;
    text += "v " + std::to_string(r * std::cos(angle)) + " " + std::to_string(r * std::sin(angle)) +
            " 0\n";
  }
  text += "f";
  for (size_t i = 0; i < corners; ++i) text += " " + std::to_string(i + 1);
  return text + "\n";
}

TEST_F(ObjLoader, ConcavePolygonKeepsItsCornersReferencesAndWinding) {
  // An arrow head, counter-clockwise from +z, with relative indices and one normal per corner.
  const MeshDesc mesh = load(
      "v 0 0 0\nv 2 1 0\nv 0 2 0\nv 0.5 1 0\nv 1 1 0\nvn 0 0 1\nf -5//1 -4//1 -3//1 -2//1 -1//1\n");
  ASSERT_EQ(mesh.triangles.size(), 3u);
  for (const MeshTriangle& t : mesh.triangles) {
    const Vec3 n = cross(mesh.positions[t.v[1]] - mesh.positions[t.v[0]],
                         mesh.positions[t.v[2]] - mesh.positions[t.v[0]]);
    EXPECT_GE(n.z, 0) << "counter-clockwise seen from +z, as written";
    for (int i = 0; i < 3; ++i) EXPECT_EQ(t.n[i], 0);
  }
}

// A face of a million corners took tinyobjloader minutes and came out as no face at all.
TEST_F(ObjLoader, HugeConvexFaceIsTriangulated) {
  const MeshDesc mesh = load(circleFace(1000000, 0));
  EXPECT_EQ(mesh.triangles.size(), 999998u);
}

TEST_F(ObjLoader, HugeConcaveFaceIsRefusedWithItsLine) {
  EXPECT_EQ(load(circleFace(kMaxConcaveFaceCorners, 2)).triangles.size(),
            kMaxConcaveFaceCorners - 2);
  EXPECT_EQ(error(circleFace(kMaxConcaveFaceCorners + 1, 2)),
            "m.obj:10002: a concave face of 10001 corners; a face that is not convex may have at "
            "most 10000 (split it into smaller faces)");
}

TEST_F(ObjLoader, NegativeIndicesCountBackFromTheLatestVertex) {
  const MeshDesc mesh =
      load("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-1 -2//-1 -1//-1\n");
  ASSERT_EQ(mesh.triangles.size(), 1u);
  expectTriangle(mesh.triangles[0], 1, 2, 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(mesh.triangles[0].n[i], 0);
}

TEST_F(ObjLoader, CrlfAndLoneCrLineEndings) {
  const MeshDesc crlf = load("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
  EXPECT_EQ(crlf.triangles.size(), 1u);
  const MeshDesc cr = load("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
  EXPECT_EQ(cr.triangles.size(), 1u);
  EXPECT_EQ(error("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 4\r\n"),
            "m.obj:4: face index 4 out of range (3 vertices)");
}

// A backslash at a line's end continues the statement on the next line (the OBJ specification);
// messages still name physical lines, and a comment ending in one (a Windows path) continues
// nothing.
TEST_F(ObjLoader, BackslashContinuesAStatementOnTheNextLine) {
  const MeshDesc mesh = load(
      "# from C:\\models\\\n"
      "v 0 0 0\nv 1 0 \\\n  0\nv 0 1 0\nv 1 1 0\n"
      "f 1 2 \\  \r\n 4 \\\n 3\n");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[1].z, 0.0f);
  ASSERT_EQ(mesh.triangles.size(), 2u);  // the quad 1 2 4 3
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\nv 0 1 \\\n0\nf 1 2 \\\n3\nf 1 2 7\n"),
            "m.obj:7: face index 7 out of range (3 vertices)");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n 2\n"),
            "m.obj:4: expected a face with at least 3 vertices, got \"f 1   2\"");
  // Continued into the end of the file.
  EXPECT_EQ(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n3").triangles.size(), 1u);
}

TEST_F(ObjLoader, VertexNormalsAreKeptPerCorner) {
  const MeshDesc mesh = load(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nvn 0 1 0\nvn 1 0 0\n"
      "f 1/1/3 2/1/2 3/1/1\n");
  ASSERT_EQ(mesh.normals.size(), 3u);
  EXPECT_FLOAT_EQ(mesh.normals[2].x, 1);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0].n[0], 2);
  EXPECT_EQ(mesh.triangles[0].n[1], 1);
  EXPECT_EQ(mesh.triangles[0].n[2], 0);
}

TEST_F(ObjLoader, FaceWithNormalsOnSomeCornersOnlyUsesTheFaceNormal) {
  const MeshDesc mesh = load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3//1\n");
  ASSERT_EQ(mesh.triangles.size(), 1u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(mesh.triangles[0].n[i], -1);
}

TEST_F(ObjLoader, MtlDiffuseColourPerFaceGroup) {
  const MeshDesc mesh = load(std::string("mtllib m.mtl\n") + kSquare +
                                 "f 1 2 3\n"
                                 "usemtl red\nf 1 3 4\n"
                                 "usemtl blue\nf 1 2 4\n"
                                 "usemtl undefined\nf 2 3 4\n",
                             "newmtl red\nKd 1 0 0\n\nnewmtl blue\r\nKd 0 0 1\r\n");
  ASSERT_EQ(mesh.triangles.size(), 4u);
  ASSERT_EQ(mesh.materials.size(), 3u);  // red, blue, and the default for the rest
  const Material& red = mesh.materials[mesh.triangles[1].material];
  EXPECT_EQ(red.type, MaterialType::Diffuse);
  EXPECT_FLOAT_EQ(red.color.x, 1);
  EXPECT_FLOAT_EQ(red.color.z, 0);
  const Material& blue = mesh.materials[mesh.triangles[2].material];
  EXPECT_FLOAT_EQ(blue.color.x, 0);
  EXPECT_FLOAT_EQ(blue.color.z, 1);
  for (int face : {0, 3}) {
    const Material& fallback = mesh.materials[mesh.triangles[face].material];
    EXPECT_FLOAT_EQ(fallback.color.x, 0.8f);
    EXPECT_FLOAT_EQ(fallback.color.z, 0.8f);
  }
  // The material no library defines is warned of, at its `usemtl` line.
  EXPECT_EQ(mesh.warnings, std::vector<std::string>{
                               "m.obj:11: no material library defines \"undefined\"; its faces "
                               "are diffuse 0.8"});
}

TEST_F(ObjLoader, MtlMaterialWithoutKdIsDefaultDiffuse) {
  const MeshDesc mesh = load(std::string("mtllib m.mtl\nusemtl plain\n") + kSquare + "f 1 2 3\n",
                             "# no colour\nnewmtl plain\nNs 10\n");
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.triangles[0].material, 0u);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.x, 0.8f);
  EXPECT_TRUE(mesh.warnings.empty());
}

// Ks turns a material glossy: plastic over Kd (index Ni), or without a diffuse colour a
// conductor of reflectance Ks; Ns sets the roughness (alpha = sqrt(2 / (Ns + 2)), roughness =
// sqrt(alpha)); Ks black leaves it diffuse.
TEST_F(ObjLoader, MtlSpecularMapsToPlasticOrConductor) {
  const MeshDesc mesh = load(std::string("mtllib m.mtl\n") + kSquare +
                                 "usemtl varnish\nf 1 2 3\n"
                                 "usemtl chrome\nf 1 3 4\n"
                                 "usemtl matte\nf 1 2 4\n",
                             "newmtl varnish\nKd 0.5 0.2 0.1\nKs 1 1 1\nNs 98\nNi 1.45\n"
                             "newmtl chrome\nKd 0 0 0\nKs 0.9 0.9 0.95\nNs 0\n"
                             "newmtl matte\nKd 0.3 0.3 0.3\nKs 0 0 0\nNs 500\nNi 1.0\n");
  const Material& varnish = mesh.materials[mesh.triangles[0].material];
  EXPECT_EQ(varnish.type, MaterialType::Plastic);
  EXPECT_FLOAT_EQ(varnish.color.x, 0.5f);
  EXPECT_FLOAT_EQ(varnish.ior, 1.45f);
  EXPECT_NEAR(varnish.roughness, std::sqrt(std::sqrt(2.0f / 100.0f)), 1e-6f);
  EXPECT_GT(varnish.plasticInternalReflectance, 0.3f);  // prepared
  const Material& chrome = mesh.materials[mesh.triangles[1].material];
  EXPECT_EQ(chrome.type, MaterialType::Conductor);
  EXPECT_FALSE(chrome.metal);
  EXPECT_FLOAT_EQ(chrome.color.z, 0.95f);
  EXPECT_FLOAT_EQ(chrome.roughness, 1.0f);  // Ns 0: alpha 1
  const Material& matte = mesh.materials[mesh.triangles[2].material];
  EXPECT_EQ(matte.type, MaterialType::Diffuse);
}

// The PBR extension's clear coat and sheen, as Blender's exporter writes them: Pc the coat's
// weight and Pcr its roughness, Ps the sheen, on the material or on both parts of a metalness
// mix; none on an emitter.
TEST_F(ObjLoader, MtlClearCoatAndSheenLayerTheMaterialOrBothItsParts) {
  const MeshDesc mesh = load(std::string("mtllib m.mtl\n") + kSquare +
                                 "usemtl paint\nf 1 2 3\n"
                                 "usemtl flake\nf 1 3 4\n"
                                 "usemtl lamp\nf 1 2 4\n",
                             "newmtl paint\nKd 0.5 0.1 0.1\nPc 0.8\nPcr 0.1\nPs 0.3\n"
                             "newmtl flake\nKd 0.5 0.5 0.5\nPm 0.5\nPr 0.4\nPc 1\n"
                             "newmtl lamp\nKe 2 2 2\nPc 1\n");
  const Material& paint = mesh.materials[mesh.triangles[0].material];
  EXPECT_EQ(paint.type, MaterialType::Diffuse);
  EXPECT_FLOAT_EQ(paint.coatWeight, 0.8f);
  EXPECT_FLOAT_EQ(paint.coatRoughness, 0.1f);
  EXPECT_GT(paint.coatTransmittance[kPlasticTableSize - 1], 0.9f);  // prepared
  EXPECT_FLOAT_EQ(paint.sheenColor.z, 0.3f);
  EXPECT_GT(paint.sheenKept[0], 0.1f);
  const Material& flake = mesh.materials[mesh.triangles[1].material];
  ASSERT_EQ(flake.type, MaterialType::Mix);
  for (const uint32_t part : flake.mixParts) {
    EXPECT_FLOAT_EQ(mesh.mixParts[part].coatWeight, 1.0f);
    EXPECT_FLOAT_EQ(mesh.mixParts[part].coatRoughness, 0.0f);
  }
  EXPECT_EQ(mesh.materials[mesh.triangles[2].material].coatWeight, 0.0f);
  ASSERT_EQ(mesh.warnings.size(), 1u);
  EXPECT_EQ(mesh.warnings[0],
            "m.mtl:13: \"Pc\" not used: material \"lamp\" is emissive, and an emissive material "
            "reflects nothing");
  dir.write("bad.mtl", "newmtl a\nKd 0.5 0.5 0.5\nPc 1.5\n");
  try {
    loadObjFile(
        dir.write("bad.obj", std::string("mtllib bad.mtl\nusemtl a\n") + kSquare + "f 1 2 3\n"),
        "bad.obj", loader);
    ADD_FAILURE() << "Pc 1.5 loaded";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.mtl:3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Pc"), std::string::npos) << e.what();
  }
}

TEST_F(ObjLoader, MtlPlasticKeepsIorWhereNiSaysNothing) {
  const MeshDesc mesh = load(std::string("mtllib m.mtl\nusemtl a\n") + kSquare + "f 1 2 3\n",
                             "newmtl a\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nNi 1.0\n");
  EXPECT_EQ(mesh.materials[0].type, MaterialType::Plastic);
  EXPECT_FLOAT_EQ(mesh.materials[0].ior, 1.5f);
}

TEST_F(ObjLoader, MissingMtlFileFallsBackToTheDefaultMaterial) {
  const MeshDesc mesh =
      load(std::string("mtllib absent.mtl\nusemtl red\n") + kSquare + "f 1 2 3\n");
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.x, 0.8f);
  EXPECT_EQ(mesh.triangles[0].material, 0u);
  // A warning names the library and its line; its materials are not warned of one by one.
  EXPECT_EQ(mesh.warnings,
            std::vector<std::string>{"m.obj:1: cannot read the material library \"absent.mtl\" "
                                     "(No such file or directory); the materials it would "
                                     "define are diffuse 0.8"});
}

TEST_F(ObjLoader, WarnsOfEachUndefinedMaterialOnceOnlyWhereTheFileNamesALibrary) {
  // `usemtl` without any `mtllib` (exporters write it for files without materials): no warning.
  EXPECT_TRUE(load(std::string("usemtl default\n") + kSquare + "f 1 2 3\n").warnings.empty());
  const MeshDesc mesh = load(std::string("mtllib m.mtl\n") + kSquare +
                                 "usemtl ghost\nf 1 2 3\nusemtl red\nf 1 3 4\n"
                                 "usemtl ghost\nf 1 2 4\nusemtl other extra words\nf 2 3 4\n",
                             "newmtl red\nKd 1 0 0\n");
  EXPECT_EQ(mesh.warnings,
            (std::vector<std::string>{
                "m.obj:6: no material library defines \"ghost\"; its faces are diffuse 0.8",
                "m.obj:12: no material library defines \"other\"; its faces are diffuse 0.8"}));
  // Beyond five, the rest are counted in one line.
  std::string many = std::string("mtllib m.mtl\n") + kSquare;
  for (int i = 0; i < 8; ++i) many += "usemtl m" + std::to_string(i) + "\nf 1 2 3\n";
  const std::vector<std::string> warnings = load(many, "newmtl red\nKd 1 0 0\n").warnings;
  ASSERT_EQ(warnings.size(), 6u);
  EXPECT_EQ(warnings[4], "m.obj:14: no material library defines \"m4\"; its faces are diffuse 0.8");
  EXPECT_EQ(warnings[5],
            "m.obj: 3 more materials that no material library defines; diffuse 0.8 in their "
            "stead");
}

TEST_F(ObjLoader, CommentsGroupsAndIgnoredStatements) {
  const MeshDesc mesh = load(
      "\xEF\xBB\xBF# header\n  o thing\ng part one\ns off\nv 0 0 0 # origin\nv 1 0 0\n"
      "v 0 1 0 1\nvt 0.5 0.5\nvp 0.1\nl 1 2\np 3\nf 1/1 2/1 3/1 # a face\n\t\n");
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

// Statements candela ignores are not handed to tinyobjloader, which parsed some itself: a skin
// weight's joint of 3e38 (undefined behaviour, found by the fuzzer) or below 0 (its own error),
// tag counts that allocate hundreds of kilobytes per line, a smoothing group beyond int.
TEST_F(ObjLoader, IgnoredStatementsNeverReachTinyobjloader) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 3e38 0\nvw 1 -1 0.5\ns 99999999999\n";
  for (int i = 0; i < 100; ++i) text += "t crease 8192/8192/8192\n";
  const MeshDesc mesh = load(text + "l 1 2\np 3\nf 1 2 3\n");
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST_F(ObjLoader, MalformedFilesNameTheLine) {
  const std::string square(kSquare);
  EXPECT_EQ(error(square + "f 1 2 99\n"), "m.obj:5: face index 99 out of range (4 vertices)");
  EXPECT_EQ(error(square + "f 1 2 -5\n"), "m.obj:5: face index -5 out of range (4 vertices)");
  EXPECT_EQ(error("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"),
            "m.obj:1: face index 1 out of range (0 vertices)");
  EXPECT_EQ(error(square + "f 1 0 2\n"),
            "m.obj:5: face index 0 is invalid (OBJ indices start at 1)");
  EXPECT_EQ(error(square + "vn 0 0 1\nf 1//1 2//2 3//1\n"),
            "m.obj:6: normal index 2 out of range (1 normal)");
  EXPECT_EQ(error(square + "f 1/1 2/1 3/1\n"),
            "m.obj:5: texture coordinate index 1 out of range (0 texture coordinates)");
  EXPECT_EQ(error(square + "f 1 2\n"),
            "m.obj:5: expected a face with at least 3 vertices, got \"f 1 2\"");
  EXPECT_EQ(error(square + "f 1 two 3\n"),
            "m.obj:5: expected a vertex reference such as 1, 1/2, 1//3 or 1/2/3, got \"two\"");
  EXPECT_EQ(error(square + "f 1/ 2 3\n"),
            "m.obj:5: expected a vertex reference such as 1, 1/2, 1//3 or 1/2/3, got \"1/\"");
  EXPECT_EQ(error("v 0 0 0\nv 1 abc 0\n"), "m.obj:2: expected a number, got \"abc\"");
  EXPECT_EQ(error("v 0 0\n"), "m.obj:1: expected a vertex \"v x y z\", got \"v 0 0\"");
  EXPECT_EQ(error("v 0 0 1e39\n"), "m.obj:1: expected a finite number, got \"1e39\"");
  EXPECT_EQ(error("vn 0 0\n"), "m.obj:1: expected a normal \"vn x y z\", got \"vn 0 0\"");
  EXPECT_EQ(error(square + "F 1 2 3\n"), "m.obj:5: unknown statement \"F\"");
  EXPECT_EQ(error("\x89PNG\r\n\x1a\n"), "m.obj:1: unknown statement \"\\x89PNG\"");
}

// Numbers in every form the grammar allows read as strtod reads them, and values beyond double's
// range as it does too: a vertex 0 below it, an error above. The scan's own reading places the
// corners of the faces it cuts into triangles: a concave pentagon written in other forms of the
// same numbers is cut the same way (where its dent, the last corner, lies decides the cut).
TEST_F(ObjLoader, NumbersReadAsStrtodReadsThem) {
  const MeshDesc plain = load("v 0 4 0\nv 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 3 0\nf 1 2 3 4 5\n");
  const MeshDesc forms =
      load("v .0 +4 0\nv +0 -0 0\nv 4.0 0 0\nv +4 4. 0\nv +2e0 .3E+1 1e-400\nf 1 2 3 4 5\n");
  ASSERT_EQ(plain.triangles.size(), 3u);
  ASSERT_EQ(forms.triangles.size(), plain.triangles.size());
  for (size_t i = 0; i < plain.triangles.size(); ++i)
    expectTriangle(forms.triangles[i], plain.triangles[i].v[0], plain.triangles[i].v[1],
                   plain.triangles[i].v[2]);

  const MeshDesc mesh = load("v +1 -0 0\nv +2.5e+0 1e-400 0\nv .5 +1. -2E-1\nf 1 2 3\n");
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[0].x, 1.0f);
  EXPECT_EQ(mesh.positions[1].x, 2.5f);
  EXPECT_EQ(mesh.positions[1].y, 0.0f);
  EXPECT_EQ(mesh.positions[2].x, 0.5f);
  EXPECT_EQ(mesh.positions[2].y, 1.0f);
  EXPECT_EQ(mesh.positions[2].z, -0.2f);
  EXPECT_EQ(error("v 0 0 1e400\n"), "m.obj:1: expected a finite number, got \"1e400\"");
  EXPECT_EQ(error(std::string(kSquare) + "f 1 2 +3\nf 1 2 +0\n"),
            "m.obj:6: face index 0 is invalid (OBJ indices start at 1)");
}

TEST_F(ObjLoader, FileWithoutFacesIsAnError) {
  EXPECT_EQ(error(kSquare), "m.obj: expected at least one face, got none");
  EXPECT_EQ(error(""), "m.obj: expected at least one face, got none");
}

TEST_F(ObjLoader, MissingFile) {
  try {
    loadObjFile("/nonexistent/candela/x.obj", "meshes/x.obj", loader);
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot open \"meshes/x.obj\" (No such file or directory)");
  }
}

// Random bytes and random statement soup: loading must end in a mesh or a SceneError.
TEST_F(ObjLoader, GarbageNeverCrashes) {
  const char* pieces[] = {"v", "vn", "vt", "f",   "l",  "p",   "g",   "usemtl", "mtllib", "#",
                          "1", "-1", "0",  "2/1", "//", "1//", "1e9", "nan",    "-2/-1",  "\t",
                          " ", "\n", "\r", "/",   "3",  "0.5", "x",   "\\",     "m.mtl",  "999"};
  uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state] {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
  };
  dir.write("m.mtl", "newmtl a\nKd 0.1 0.2 0.3\n");
  for (int round = 0; round < 1500; ++round) {
    std::string text;
    const bool bytes = round % 3 == 0;
    const int length = static_cast<int>(next() % 200);
    for (int i = 0; i < length; ++i) {
      if (bytes) {
        text += static_cast<char>(next() & 0xFF);
      } else {
        text += pieces[next() % (sizeof pieces / sizeof pieces[0])];
        text += next() % 3 ? " " : "\n";
      }
    }
    if (round % 5 == 0) text = std::string(kSquare) + text;
    try {
      const MeshDesc mesh = load(text);
      for (const MeshTriangle& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) {
          ASSERT_LT(t.v[i], mesh.positions.size());
          ASSERT_LT(t.n[i], static_cast<int32_t>(mesh.normals.size()));
          ASSERT_LT(t.material, mesh.materials.size());
        }
    } catch (const SceneError&) {
      // Refusing garbage is the expected outcome; crashing or accepting bad indices is not.
    }
  }
}

TEST(ObjAsset, CatLoadsWithItsMaterial) {
  const char* assets = std::getenv("CANDELA_ASSETS");
  const std::string path =
      (assets ? std::string(assets) : std::string(CANDELA_SOURCE_DIR) + "/../shared/assets") +
      "/cat/cat.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared asset " << path << " is not present";
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  TextureLoader loader(textures, ".");
  const MeshDesc mesh = loadObjFile(path, "cat.obj", loader);
  EXPECT_EQ(mesh.triangles.size(), 3954u);
  EXPECT_EQ(mesh.positions.size(), 2247u);
  EXPECT_EQ(mesh.normals.size(), 2152u);
  ASSERT_EQ(mesh.materials.size(), 1u);  // "cat" from cat.mtl, used by every face
  EXPECT_EQ(mesh.materials[0].type, MaterialType::Diffuse);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.x, 1);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.y, 1);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.z, 1);
  // map_Kd and map_d name cat_diff.png, a 512x1024 RGBA image: read once as colour, once as mask.
  ASSERT_EQ(textures.size(), 2u);
  EXPECT_EQ(textures[0]->width, 512u);
  EXPECT_EQ(textures[0]->height, 1024u);
  EXPECT_EQ(mesh.materials[0].colorTexture.index, 0);
  EXPECT_EQ(mesh.materials[0].alpha.texture.index, 1);
  EXPECT_EQ(mesh.materials[0].alpha.channel, 3u);
  EXPECT_FALSE(mesh.uvs.empty());
  for (const MeshTriangle& t : mesh.triangles) {
    ASSERT_EQ(t.material, 0u);
    ASSERT_GE(t.n[0], 0);
  }
}

}  // namespace
}  // namespace candela
