// The header of a Stanford PLY file: its format and the elements and properties that follow.
//
//   ply
//   format binary_little_endian 1.0        (or ascii 1.0, binary_big_endian 1.0)
//   comment ...                            (and obj_info: ignored)
//   element vertex 8
//   property float x                       (char uchar short ushort int uint float double, or
//   property list uchar int vertex_indices  int8 uint8 int16 uint16 int32 uint32 float32 float64)
//   end_header
//
// Lines end in \n or \r\n. Errors throw SceneError "<label>:<line>: <reason>".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class PlyType { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

size_t plySize(PlyType type);           // bytes of a binary value
const char* plyTypeName(PlyType type);  // as the specification spells it: "uchar", "float", ...

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the values (a list's items)
  bool isList = false;
  PlyType countType = PlyType::Uint8;  // of a list's count
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
  size_t line = 0;  // of its `element` statement
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  size_t bodyOffset = 0;  // the first byte after end_header's line
  size_t lines = 0;       // the header's lines, so that an ASCII body's lines number on from it
};

PlyHeader readPlyHeader(const std::string& bytes, const std::string& label);

}  // namespace candela
