// evalBsdf and its pdf against Mitsuba 3.9.1 (scalar_rgb) on the same materials and directions:
// roughconductor (GGX, material "none" with a reflectance, and "Au"), roughdielectric (GGX,
// int_ior 1.5: reflection and transmission from both sides), both also anisotropic (alpha_u and
// alpha_v from candela's roughness and anisotropy, render/microfacet.h), plastic and roughplastic
// (int_ior 1.5, nonlinear false). The numbers are Mitsuba's BSDF::eval (f times the cosine, as
// evalBsdf) and BSDF::pdf, printed by a script that loads each material with mi.load_dict;
// Mitsuba's incident direction si.wi is candela's wo. The shading frame is the geometric one, +z
// up.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "render/bsdf.h"
#include "render/material_prepare.h"
#include "untextured_bsdf.h"

namespace candela {
namespace {

Vec3 direction(float cosTheta, float phi) {
  const float s = std::sqrt(1.0f - cosTheta * cosTheta);
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// (wo, wi) pairs: index k of the table below.
const Vec3 kPairs[][2] = {
    {direction(0.9f, 0.3f), direction(0.8f, 3.3f)},
    {direction(0.5f, 1.0f), direction(0.6f, 4.0f)},
    {direction(0.3f, 0.0f), direction(0.95f, 2.0f)},
    {direction(0.9f, 0.3f), direction(-0.7f, 3.5f)},
    {direction(-0.8f, 0.3f), direction(0.6f, 3.0f)},
    {direction(0.7f, 0.1f), direction(-0.9f, 3.0f)},
    // Mirror pairs across the bitangent and across the tangent, for the anisotropic lobes.
    {direction(0.6f, 1.4f), direction(0.7f, 4.6f)},
    {direction(0.6f, 0.2f), direction(0.7f, 3.2f)},
};

Material material(const std::string& name) {
  Material m;
  if (name == "cond03") {
    m.type = MaterialType::Conductor;
    m.roughness = 0.3f;
    m.color = Vec3(0.9f, 0.8f, 0.7f);
  } else if (name == "au06") {
    m.type = MaterialType::Conductor;
    m.roughness = 0.6f;
    m.color = Vec3(1.0f);
    m.metal = true;
    m.metalEta = Vec3(0.143036f, 0.375307f, 1.44205f);  // Mitsuba's RGB gold
    m.metalK = Vec3(3.983f, 2.38556f, 1.60336f);
  } else if (name == "acond") {  // Mitsuba's alpha_u 0.338643, alpha_v 0.101593
    m.type = MaterialType::Conductor;
    m.roughness = 0.5f;
    m.anisotropy = 0.7f;
    m.color = Vec3(0.9f, 0.8f, 0.7f);
  } else if (name == "aglass") {  // alpha_u 0.328266, alpha_v 0.131306
    m.type = MaterialType::Glass;
    m.roughness = 0.5f;
    m.anisotropy = 0.6f;
    m.color = Vec3(1.0f);
  } else if (name == "glass04" || name == "glass07") {
    m.type = MaterialType::Glass;
    m.roughness = name == "glass04" ? 0.4f : 0.7f;
    m.color = Vec3(1.0f);
  } else {
    m.type = MaterialType::Plastic;
    m.roughness = name == "plastic0" ? 0.0f : 0.3f;
    m.color = Vec3(0.6f, 0.3f, 0.2f);
  }
  m.ior = 1.5f;
  prepareMaterial(&m);
  return m;
}

TEST(BsdfAgainstMitsuba, EvalAndPdfMatch) {
  const struct {
    const char* material;
    int pair;
    Vec3 f;
    float pdf;
  } references[] = {
      {"cond03", 0, {1.77916f, 1.58148f, 1.38379f}, 1.97909f},
      {"cond03", 1, {2.20687f, 1.96166f, 1.71645f}, 2.46087f},
      {"cond03", 2, {0.0171364f, 0.0152323f, 0.0133283f}, 0.0190446f},
      {"au06", 0, {0.557395f, 0.462342f, 0.188362f}, 0.587121f},
      {"au06", 1, {0.851515f, 0.709333f, 0.316749f}, 0.93234f},
      {"au06", 2, {0.152969f, 0.126881f, 0.052492f}, 0.158939f},
      {"glass04", 0, {0.0713938f, 0.0713938f, 0.0713938f}, 0.0716499f},
      {"glass04", 1, {0.182601f, 0.182601f, 0.182601f}, 0.184656f},
      {"glass04", 2, {0.00248083f, 0.00248083f, 0.00248083f}, 0.00248255f},
      {"glass04", 3, {0.0117905f, 0.0117905f, 0.0117905f}, 0.0267041f},
      {"glass04", 4, {0.181818f, 0.181818f, 0.181818f}, 0.0817171f},
      {"glass04", 5, {1.41121f, 1.41121f, 1.41121f}, 3.17999f},
      {"glass07", 0, {0.0137392f, 0.0137392f, 0.0137392f}, 0.0141884f},
      {"glass07", 1, {0.0353342f, 0.0353342f, 0.0353342f}, 0.0387705f},
      {"glass07", 2, {0.00854831f, 0.00854831f, 0.00854831f}, 0.00860338f},
      {"glass07", 3, {0.101402f, 0.101402f, 0.101402f}, 0.241614f},
      {"glass07", 4, {0.687252f, 0.687252f, 0.687252f}, 0.335151f},
      {"glass07", 5, {1.22902f, 1.22902f, 1.22902f}, 2.80369f},
      {"acond", 0, {1.80401f, 1.60357f, 1.40312f}, 2.03557f},
      {"acond", 1, {0.811682f, 0.721495f, 0.631308f}, 0.923366f},
      {"acond", 2, {0.129453f, 0.115069f, 0.100686f}, 0.143947f},
      {"acond", 6, {1.84869f, 1.64328f, 1.43787f}, 2.06029f},
      {"acond", 7, {1.00047f, 0.889307f, 0.778143f}, 1.14377f},
      {"aglass", 0, {0.0681715f, 0.0681715f, 0.0681715f}, 0.0691684f},
      {"aglass", 1, {0.0869237f, 0.0869237f, 0.0869237f}, 0.0890327f},
      {"aglass", 2, {0.00793106f, 0.00793106f, 0.00793106f}, 0.0079381f},
      {"aglass", 3, {0.0377342f, 0.0377342f, 0.0377342f}, 0.0869853f},
      {"aglass", 4, {0.0512992f, 0.0512992f, 0.0512992f}, 0.023827f},
      {"aglass", 5, {0.533026f, 0.533026f, 0.533026f}, 1.20671f},
      {"aglass", 6, {0.114526f, 0.114526f, 0.114526f}, 0.115071f},
      {"aglass", 7, {0.0732801f, 0.0732801f, 0.0732801f}, 0.0752746f},
      {"plastic0", 0, {0.154461f, 0.0772305f, 0.051487f}, 0.228183f},
      {"plastic0", 1, {0.107627f, 0.0538137f, 0.0358758f}, 0.150732f},
      {"plastic0", 2, {0.152084f, 0.0760419f, 0.0506946f}, 0.176303f},
      {"plastic03", 0, {0.222942f, 0.152819f, 0.129445f}, 0.438228f},
      {"plastic03", 1, {0.278939f, 0.23032f, 0.214113f}, 0.686514f},
      {"plastic03", 2, {0.141232f, 0.0710539f, 0.0476612f}, 0.188922f},
  };
  const Vec3 up(0.0f, 0.0f, 1.0f);
  for (const auto& r : references) {
    const Material m = material(r.material);
    // Plastic's tables come from a quadrature of candela's own: 1%; the rest are closed forms.
    const float tolerance = std::strncmp(r.material, "plastic", 7) == 0 ? 0.01f : 0.002f;
    const Vec3& wo = kPairs[r.pair][0];
    const Vec3& wi = kPairs[r.pair][1];
    float pdf;
    const Vec3 f = evalBsdf(untexturedBsdf(m, wo, up, up), wi, &pdf);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(f[a], r.f[a], tolerance * r.f[a]) << r.material << " pair " << r.pair;
    EXPECT_NEAR(pdf, r.pdf, tolerance * r.pdf) << r.material << " pair " << r.pair;
  }
}

}  // namespace
}  // namespace candela
