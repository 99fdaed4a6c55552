// The B-rep models of ../shared the adapter's tests run over: models/*.brep, models/cad/*.step and
// *.brep, models/corpus/*.brep.
#pragma once
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace bisect::test {

// Paths relative to BISECT_SHARED_DIR, sorted; empty when ../shared is missing.
inline std::vector<std::string> shared_brep_models() {
  namespace fs = std::filesystem;
  const fs::path root(BISECT_SHARED_DIR);
  std::vector<std::string> out;
  for (const char* dir : {"models", "models/cad", "models/corpus"}) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(root / dir, ec)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".brep" || ext == ".step") out.push_back(fs::relative(entry.path(), root).string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// "models/corpus/x_ring.brep" -> "corpus_x_ring_brep"
inline std::string shared_test_name(const std::string& path) {
  std::string s = path.rfind("models/", 0) == 0 ? path.substr(7) : path;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

}  // namespace bisect::test
