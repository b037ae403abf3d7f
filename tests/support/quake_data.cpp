#include "tests/support/quake_data.h"

#include <cstdlib>
#include <filesystem>

namespace sb::test {

std::string quake_dir() {
  const char* env = std::getenv("STARBOW_QUAKE_DIR");
  std::string dir = env && *env ? env : STARBOW_QUAKE_DIR;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir + "/lq1", ec)) return {};
  return dir;
}

}  // namespace sb::test
