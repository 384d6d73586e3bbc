#include "common/fclib_collection.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <string>

namespace impactbench::bench {

std::vector<std::filesystem::path> collection_files(const std::filesystem::path& folder,
                                                    const std::string& extension) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == extension) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::filesystem::path> fclib_collection_files(const std::filesystem::path& folder) {
  return collection_files(folder, ".hdf5");
}

const solvers::FclibProblem& cached_fclib_problem(const std::filesystem::path& path) {
  static std::map<std::string, std::unique_ptr<solvers::FclibProblem>> cache;
  auto& slot = cache[path.string()];
  if (!slot) slot = std::make_unique<solvers::FclibProblem>(solvers::read_fclib_file(path));
  return *slot;
}

}  // namespace impactbench::bench
