// The model cache is verified before anything in it is loaded (docs/models.md, "The cache"): a
// changed, truncated, empty or foreign object, a directory at the object's path or a garbled
// manifest is a miss (compiled again: the shipped fput's numbers, never a crash or another model's
// numbers); a cache directory writable by others or owned by another user is refused naming it;
// temporaries of dead compiles are removed by the next compile.
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/model_compiler.hpp"
#include "scratch_cache.hpp"

namespace fs = std::filesystem;
using namespace lrchain;

namespace {

struct Scratch : test::ScratchCache {
  Scratch() : ScratchCache("lrchain-cache-test") {}
};

// models/<shipped>.toml under the name `name` at `path`.
void write_renamed(const std::string& shipped, const std::string& name, const fs::path& path) {
  std::ifstream in(fs::path(LRCHAIN_SOURCE_DIR) / "models" / (shipped + ".toml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string from = "name = \"" + shipped + "\"";
  s.replace(s.find(from), from.size(), "name = \"" + name + "\"");
  std::ofstream(path) << s;
}

std::vector<fs::path> objects(const fs::path& cache, const std::string& prefix) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(cache))
    if (e.path().filename().string().rfind(prefix, 0) == 0 && e.path().extension() == ".so") found.push_back(e.path());
  return found;
}

// gamma and h of fput at theta = 1 on its branch, the reference (compiled-in evaluators).
void check_fput_numbers(const std::shared_ptr<const ModelDefinition>& d) {
  const Model mine(d), shipped = shipped_model("fput");
  const auto a = coefficients(mine, 0, 1.0), b = coefficients(shipped, 0, 1.0);
  CHECK(a.gamma == doctest::Approx(b.gamma).epsilon(1e-12));
  CHECK(a.h == doctest::Approx(b.h).epsilon(1e-12));
}

}  // namespace

TEST_CASE("model cache: every corruption of an entry is a miss, compiled again with the right numbers" *
          doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  write_renamed("fput", "mine", scratch.dir / "mine.toml");
  write_renamed("klein_gordon", "other", scratch.dir / "other.toml");
  CompiledModelInfo info;
  check_fput_numbers(compile_model_file(scratch.dir / "mine.toml", &info));
  CHECK(!info.from_cache);
  REQUIRE(objects(scratch.cache(), "model-").size() == 1);
  compile_model_file(scratch.dir / "other.toml");
  REQUIRE(objects(scratch.cache(), "model-").size() == 2);
  const fs::path mine = info.library;
  REQUIRE(fs::exists(mine));
  // Reused while intact.
  check_fput_numbers(compile_model_file(scratch.dir / "mine.toml", &info));
  CHECK(info.from_cache);

  const std::vector<std::pair<std::string, std::function<void(const fs::path&)>>> corruptions{
      {"garbage", [](const fs::path& p) { std::ofstream(p, std::ios::binary | std::ios::trunc) << std::string(4096, '\x5a'); }},
      {"truncated", [](const fs::path& p) { fs::resize_file(p, fs::file_size(p) / 2); }},
      {"empty", [](const fs::path& p) { fs::resize_file(p, 0); }},
      {"one byte changed",
       [](const fs::path& p) {
         std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
         f.seekp(std::streamoff(fs::file_size(p) / 2));
         f.put('\x01');
       }},
      {"a directory", [](const fs::path& p) {
         fs::remove(p);
         fs::create_directory(p);
       }}};
  for (const auto& [what, corrupt] : corruptions) {
    CAPTURE(what);
    compile_model_file(scratch.dir / "mine.toml", &info);  // an intact entry to corrupt
    const fs::path object = info.library;
    corrupt(object);
    check_fput_numbers(compile_model_file(scratch.dir / "mine.toml", &info));
    CHECK(!info.from_cache);
    CHECK(info.library != object);  // a fresh object
    CHECK(fs::is_regular_file(info.library));
  }
  // The manifest garbled, or gone.
  for (const std::string& text : {std::string("not a hash\n"), std::string(64, 'f') + "\n", std::string()}) {
    compile_model_file(scratch.dir / "mine.toml", &info);
    fs::path manifest = info.library;
    manifest.replace_extension("").replace_extension(".manifest");
    REQUIRE(fs::exists(manifest));
    if (text.empty()) fs::remove(manifest);
    else std::ofstream(manifest, std::ios::trunc) << text;
    check_fput_numbers(compile_model_file(scratch.dir / "mine.toml", &info));
    CHECK(!info.from_cache);
  }
  // Another model's object and manifest copied over this entry: loaded, found foreign, compiled again.
  compile_model_file(scratch.dir / "mine.toml", &info);
  fs::path mine_manifest = info.library;
  mine_manifest.replace_extension("").replace_extension(".manifest");
  CompiledModelInfo other;
  compile_model_file(scratch.dir / "other.toml", &other);
  fs::path other_manifest = other.library;
  other_manifest.replace_extension("").replace_extension(".manifest");
  const std::string stem = mine_manifest.stem().string();
  const std::string other_name = other.library.filename().string();
  fs::copy_file(other.library, scratch.cache() / (stem + other_name.substr(other_name.find('.'))), fs::copy_options::overwrite_existing);
  fs::copy_file(other_manifest, mine_manifest, fs::copy_options::overwrite_existing);
  const auto definition = compile_model_file(scratch.dir / "mine.toml", &info);
  CHECK(definition->name == "mine");
  check_fput_numbers(definition);
  CHECK(!info.from_cache);
}

TEST_CASE("model cache: a compiled object corrupted is compiled again, kernels included, not loaded" * doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  write_renamed("fput", "mine", scratch.dir / "mine.toml");
  CompiledModelInfo info;
  compile_model_file(scratch.dir / "mine.toml", &info);
  const fs::path object = info.library;
  fs::resize_file(object, fs::file_size(object) / 3);
  const auto kernels = compile_model_lattice(scratch.dir / "mine.toml", &info);
  CHECK(std::string(kernels->model_name) == "mine");
  CHECK(!info.from_cache);
  CHECK(info.library != object);
}

TEST_CASE("model cache: a cache writable by others or owned by another user is refused naming it" * doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  write_renamed("fput", "mine", scratch.dir / "mine.toml");
  compile_model_file(scratch.dir / "mine.toml");
  fs::permissions(scratch.cache(), fs::perms::all);  // 0777
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "mine.toml"),
                       doctest::Contains(("the model cache " + scratch.cache().string() + " is writable by group or others").c_str()),
                       InputError);
  fs::permissions(scratch.cache(), fs::perms::owner_all);
  CHECK_NOTHROW(compile_model_file(scratch.dir / "mine.toml"));
  if (::geteuid() != 0) return;  // giving a directory to another user needs root
  const uid_t nobody = 65534;
  REQUIRE(::chown(scratch.cache().c_str(), nobody, nobody) == 0);
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "mine.toml"),
                       doctest::Contains(("the model cache " + scratch.cache().string() + " belongs to another user").c_str()),
                       InputError);
  REQUIRE(::chown(scratch.cache().c_str(), 0, 0) == 0);
  // XDG_CACHE_HOME itself another user's and world-writable (e.g. a shared /tmp directory).
  const fs::path shared = scratch.dir / "shared";
  fs::create_directory(shared);
  fs::permissions(shared, fs::perms::all);
  REQUIRE(::chown(shared.c_str(), nobody, nobody) == 0);
  ::setenv("XDG_CACHE_HOME", shared.c_str(), 1);
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "mine.toml"), doctest::Contains(shared.c_str()), InputError);
  CHECK(!fs::exists(shared / "lrchain"));
}

TEST_CASE("model cache: temporaries of a compile killed mid-way are removed by the next compile" * doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  write_renamed("fput", "mine", scratch.dir / "mine.toml");
  write_renamed("fput", "second", scratch.dir / "second.toml");
  compile_model_file(scratch.dir / "mine.toml");
  // A pid that is certainly dead: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  REQUIRE(child > 0);
  ::waitpid(child, nullptr, 0);
  const std::string dead = ".model-" + std::to_string(child) + "-12345";
  const std::string alive = ".model-" + std::to_string(::getppid()) + "-12345";  // our parent runs
  for (const std::string& name : {dead + ".cpp", dead + ".so", dead + ".manifest", alive + ".cpp"})
    std::ofstream(scratch.cache() / name) << "left by a killed compile";
  compile_model_file(scratch.dir / "second.toml");
  CHECK(!fs::exists(scratch.cache() / (dead + ".cpp")));
  CHECK(!fs::exists(scratch.cache() / (dead + ".so")));
  CHECK(!fs::exists(scratch.cache() / (dead + ".manifest")));
  CHECK(fs::exists(scratch.cache() / (alive + ".cpp")));  // a compile that may still run is left alone
}
