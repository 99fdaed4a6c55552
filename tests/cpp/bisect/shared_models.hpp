// The polyhedral inputs of ../shared that the decomposition tests run over, and test names for them.
#pragma once
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace bisect::test {

inline const std::vector<std::string> kSharedPolyhedralInputs = {
    "examples/cube-cavity-adjacent-cube.poly", "examples/reentry-box.poly", "models/stl/Angled.stl",
    "models/stl/bl3d_4.stl", "models/stl/box-cavity.stl", "models/stl/cantilever.stl", "models/stl/flange.stl",
    "models/stl/lug.stl", "models/stl/part.stl", "models/stl/plate-hole.stl", "models/stl/slender-appendage.stl"};

// "models/stl/plate-hole.stl" -> "plate_hole"
inline std::string test_name_of(const std::string& path) {
  std::string s = std::filesystem::path(path).stem().string();
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

}  // namespace bisect::test
