#include "shipped_data.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "report/lrchain_process.hpp"

namespace lrchain::cli {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_data_roots() {
  const fs::path exe_dir = report::current_executable().parent_path();
  std::vector<fs::path> roots{exe_dir.parent_path() / "share/lrchain"};
  if (std::ifstream tree{exe_dir / "lrchain-source-tree"}; tree) {
    std::string source_dir;
    if (std::getline(tree, source_dir) && !source_dir.empty()) roots.emplace_back(source_dir);
  }
  return roots;
}

std::string resolve_model_argument(const std::string& text) {
  std::error_code ec;
  const bool named = !text.empty() && text.find('/') == std::string::npos &&
                     !(text.size() > 5 && text.ends_with(".toml")) && !fs::exists(text, ec);  // a FIFO or device is the reader's to refuse
  if (!named) return text;
  std::vector<std::string> shipped;
  for (const fs::path& root : shipped_data_roots()) {
    const fs::path models = root / "models";
    if (!fs::is_directory(models, ec)) continue;
    const fs::path file = models / (text + ".toml");
    if (fs::is_regular_file(file, ec)) return file.string();
    for (const auto& entry : fs::directory_iterator(models, ec))
      if (entry.path().extension() == ".toml") shipped.push_back(entry.path().stem().string());
    break;  // the names of the first models/ found
  }
  if (shipped.empty())
    throw InputError("--model " + text + ": no such file, and no shipped models were found (share/lrchain/models "
                     "beside this lrchain); give the path of a model file");
  std::sort(shipped.begin(), shipped.end());
  throw InputError(fmt::format("--model {}: no such file or shipped model; the shipped models are {}", text,
                               fmt::join(shipped, ", ")));
}

}  // namespace lrchain::cli
