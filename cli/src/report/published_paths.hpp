#pragma once
// The report is built in DIR.partial and renamed to DIR when complete; the JSON files its runs wrote
// name the directory they ran in. This points them at DIR before the rename.
#include <filesystem>

namespace lrchain::report {

// In every *.json file under `building`, rewrites the fields that name output paths ("out",
// "checkpoint_file" and the elements of "command_line", at any depth) from `building` to `published`;
// each changed file is written to a temporary name and renamed. Other fields and files are left as
// they are. Throws std::runtime_error naming a file it cannot read, parse or write.
void point_json_files_at(const std::filesystem::path& building, const std::filesystem::path& published);

}  // namespace lrchain::report
