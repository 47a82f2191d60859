// What a material derives from its parameters once, on the host, before rendering: the plastic's
// internal reflectance and coating transmittance table (render/bsdf_plastic.h), and smooth glass
// in place of rough glass of index 1.
#pragma once

#include <vector>

#include "render/material.h"

namespace candela {

// Fills m's derived fields from its type, ior and roughness. Idempotent.
void prepareMaterial(Material* m);

// The coat rows of a plastic of index eta whose roughness is textured (Material::
// plasticCoatTable): for each of kPlasticCoatLevels roughness levels (plasticCoatLevelRoughness),
// its transmittance table and its internal reflectance.
std::vector<float> plasticCoatTable(float eta);

// The sheen's tables by roughness level for the sheens whose roughness is textured
// (SceneView::sheenTables): kSheenLevels rows of kSheenRow (the lobe's albedo, then the normalized
// lobe's; render/surface_layers.h, sheenLevelRoughness), those from level `first` to `last` filled
// and the rest zero. Each level is made once per process (about 20 ms of one core's time).
std::vector<float> sheenLevelTables(uint32_t first, uint32_t last);

// The share of light arriving at cos(theta) = mu that a GGX dielectric coating (relative index
// eta, alpha >= kSmoothAlpha) reflects, and the share it transmits, in single scattering (the
// integrals of its BRDF and BTDF times the cosine, by quadrature over the visible normals).
double roughCoatReflectance(double mu, float eta, float alpha);
double roughCoatTransmittance(double mu, float eta, float alpha);

}  // namespace candela
