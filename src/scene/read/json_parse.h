// Scene text -> JSON document, with errors that point at the fault.
//
// Strict JSON (no comments, no trailing commas). Failures throw SceneError:
//   syntax:              "<file>:<line>:<column>: invalid JSON: <reason>"   (both 1-based, bytes)
//   number overflow:     "<file>: <path>: expected a finite number, got 1e400"
//   duplicate key:       "<file>: <path>: duplicate key, each key may appear once per object"
// Duplicate keys would otherwise silently override each other; comment keys ('_...') may repeat.
#pragma once

#include <string>

#include "scene/read/json_reader.h"

namespace candela {

Json parseJson(const std::string& text, const std::string& file);

}  // namespace candela
