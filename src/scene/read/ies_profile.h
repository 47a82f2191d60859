// IES photometric files (ANSI/IESNA LM-63, as lighting makers publish for their fixtures, in its
// 1986, 1991, 1995 and 2002 versions): a lamp's candela values over type C angles, read into a
// light profile (render/light_profile.h).
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace candela {

struct IesProfile {
  // Vertical angles in degrees from the nadir (0 or 90 to 90 or 180, increasing) and horizontal
  // ones, the C-planes (0 alone: the same in every plane; 0 to 90, 180 or 360; or 90 to 270).
  std::vector<double> vertical, horizontal;
  std::vector<double> candela;  // horizontal.size() runs of vertical.size() values
};

// The file at `path`, shown as `label` in messages: throws SceneError "<label>:<line>: <what was
// expected>" for a file that is not LM-63 with TILT=NONE and type C photometry, or whose
// numbers are missing, not finite or negative, or whose angles are out of order or range.
IesProfile readIesProfile(const std::string& path, const std::string& label);

// The profile's candela value at vertical angle theta and C-plane phi (degrees): linear between
// the file's angles, in both, and unfolded by the file's symmetry; 0 beyond its vertical range.
double iesValue(const IesProfile& profile, double theta, double phi);

// The profile on the grid render/light_profile.h reads, as a float texture (its R channel): one
// column where the profile is the same in every C-plane.
TextureDesc profileTexture(const IesProfile& profile, const std::string& file);

// The mean over the sphere of a profile texture's bilinear values between vertical angles
// `first` and `last` (degrees), as render/light_profile.h reads them (its scale is the inverse).
double profileTextureMean(const TextureDesc& texture, double first, double last);

}  // namespace candela
