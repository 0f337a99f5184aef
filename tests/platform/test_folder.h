// A fresh folder for one platform test's files, under the build's test output
// ($VKRT_TEST_OUTPUT, which ctest sets) or else the system's temporary folder. Standard C++
// only: the platform tests build for Windows too.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace vkrt::test {

inline std::string freshFolder(const std::string& name) {
  namespace fs = std::filesystem;
  const char* root = std::getenv("VKRT_TEST_OUTPUT");
  const fs::path dir = (root && *root ? fs::path(root) : fs::temp_directory_path()) / "platform" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

}  // namespace vkrt::test
