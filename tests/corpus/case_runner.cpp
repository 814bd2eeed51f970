// One corpus case in a fresh directory, with a timeout, checked against the rules of bad input
// (case_runner.hpp): exit 2, one stderr line naming the option/key/file, nothing new on disk.
#include "case_runner.hpp"

#include <signal.h>
#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <condition_variable>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>
#include <tuple>

#include "lrchain/process.hpp"

namespace lrchain::corpus {

namespace fs = std::filesystem;

namespace {

using Tree = std::map<std::string, std::tuple<char, std::uintmax_t, long long>>;

// Every path under `dir` with its kind, size and modification time.
Tree snapshot(const fs::path& dir) {
  Tree t;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const auto st = it->symlink_status(ec);
    const char kind = fs::is_directory(st) ? 'd' : fs::is_symlink(st) ? 'l' : 'f';
    const std::uintmax_t size = kind == 'f' ? it->file_size(ec) : 0;
    const long long mtime = kind == 'l' ? 0 : it->last_write_time(ec).time_since_epoch().count();
    t[fs::relative(it->path(), dir).string()] = {kind, size, mtime};
  }
  return t;
}

// "+ new", "- removed", "~ changed" paths, at most a few.
std::string tree_difference(const Tree& before, const Tree& after) {
  std::vector<std::string> diff;
  for (const auto& [p, v] : after) {
    const auto it = before.find(p);
    if (it == before.end()) diff.push_back("+" + p + (std::get<0>(v) == 'd' ? "/" : ""));
    else if (it->second != v) diff.push_back("~" + p);
  }
  for (const auto& [p, v] : before)
    if (!after.count(p)) diff.push_back("-" + p);
  std::string s;
  for (std::size_t i = 0; i < diff.size() && i < 6; ++i) s += (i ? " " : "") + diff[i];
  if (diff.size() > 6) s += " ... (" + std::to_string(diff.size()) + " paths)";
  return s;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
  return s;
}

std::string shell_quoted(const std::string& a) {
  if (!a.empty() && a.find_first_of(" \t\n'\"$`\\;&|<>()*?[]{}!#~") == std::string::npos) return a;
  return "'" + replace_all(a, "'", "'\\''") + "'";
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Sends SIGTERM at the deadline, SIGKILL two seconds later, unless the child ended before.
class Watchdog {
 public:
  Watchdog(const ChildProcess& child, std::chrono::milliseconds timeout)
      : thread_([this, &child, timeout] {
          std::unique_lock lock(mutex_);
          if (ended_.wait_for(lock, timeout, [this] { return done_; })) return;
          fired_ = true;
          child.send_signal(SIGTERM);
          if (ended_.wait_for(lock, std::chrono::seconds(2), [this] { return done_; })) return;
          child.send_signal(SIGKILL);
        }) {}
  // Called once the child has been reaped; returns whether the deadline passed.
  bool finish() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    ended_.notify_all();
    thread_.join();
    return fired_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable ended_;
  bool done_ = false, fired_ = false;
  std::thread thread_;
};

bool word_letter(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

}  // namespace

bool names(const std::string& text_in, const std::string& name_in) {
  const std::string text = replace_all(text_in, "_", "-"), name = replace_all(name_in, "_", "-");
  if (name.empty()) return false;
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    const std::size_t end = at + name.size();
    // A '-' joins words ("front-fit-start"), unless it starts an option ("--t-end").
    const bool left = at == 0 || (!word_letter(text[at - 1]) &&
                                  !(text[at - 1] == '-' && at >= 2 && word_letter(text[at - 2])));
    const bool right = end == text.size() || (!word_letter(text[end]) &&
                                              !(text[end] == '-' && end + 1 < text.size() && word_letter(text[end + 1])));
    if (left && right) return true;
  }
  return false;
}

CaseOutcome run_case(const CorpusCase& c, const RunSettings& settings) {
  CaseOutcome out;
  std::string pattern = (settings.scratch / "case-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) {
    out.broken.push_back({"setup", "mkdtemp failed under " + settings.scratch.string()});
    return out;
  }
  const fs::path root = pattern, work = root / "work";
  fs::create_directories(work / "tmp");
  for (const auto& d : c.directories) fs::create_directories(work / d);
  for (const auto& [name, bytes] : c.files) std::ofstream(work / name, std::ios::binary) << bytes;

  std::vector<std::string> argv{settings.lrchain};
  for (const auto& a : c.args)
    argv.push_back(replace_all(replace_all(a, "@OUT@", "@TMP@/out"), "@TMP@", work.string()));
  out.command_line = "lrchain";
  for (std::size_t i = 1; i < argv.size(); ++i)
    out.command_line += " " + shell_quoted(replace_all(argv[i], work.string(), "TMP"));

  const Tree before = snapshot(work);
  ProcessOptions po;
  po.working_directory = work;
  po.stdout_file = root / "stdout";
  po.stderr_file = root / "stderr";
  po.environment = settings.environment;
  po.environment.push_back("TMPDIR=" + (work / "tmp").string());
  po.environment.push_back("XDG_CACHE_HOME=" + (work / "cache").string());
  po.environment.push_back("HOME=" + (work / "home").string());
  const auto start = std::chrono::steady_clock::now();
  ProcessResult r;
  bool timed_out = false;
  {
    ChildProcess child(argv, po);
    // A control is a valid run, not the subject of the "ends within seconds" rule: thrice the time.
    Watchdog watchdog(child, c.control ? 3 * settings.timeout : settings.timeout);
    r = child.wait();
    timed_out = watchdog.finish();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.error_output = read_all(root / "stderr");
  out.exit_code = r.exited ? r.exit_code : -1;
  out.signal_number = r.signal_number;
  const Tree after = snapshot(work);
  if (!settings.keep_directories) fs::remove_all(root);

  const double limit = std::chrono::duration<double>(c.control ? 3 * settings.timeout : settings.timeout).count();
  if (timed_out) out.broken.push_back({"timeout", "still running after " + std::to_string(int(limit)) + " s, killed"});
  else if (!r.exited) out.broken.push_back({"killed by a signal", "signal " + std::to_string(r.signal_number)});
  if (c.control) {
    if (r.exited && r.exit_code != 0)
      out.broken.push_back({"control: exit code", "exit " + std::to_string(r.exit_code) + " (a valid base must exit 0)"});
    return out;
  }
  if (r.exited && r.exit_code != 2) out.broken.push_back({"exit code", "exit " + std::to_string(r.exit_code) + " (want 2)"});
  const auto newlines = std::count(out.error_output.begin(), out.error_output.end(), '\n');
  if (newlines != 1 || out.error_output.back() != '\n')
    out.broken.push_back({"stderr lines", std::to_string(newlines) + " lines on stderr (want exactly 1)"});
  for (const auto& n : c.names)
    if (!names(out.error_output, n)) out.broken.push_back({"names", "stderr does not name '" + n + "'"});
  if (!c.any_name.empty() &&
      std::none_of(c.any_name.begin(), c.any_name.end(), [&](const auto& n) { return names(out.error_output, n); }))
    out.broken.push_back({"names", "stderr names neither '" + c.any_name.front() + "' nor '" + c.any_name.back() + "'"});
  for (const auto& s : c.substrings)
    if (out.error_output.find(s) == std::string::npos)
      out.broken.push_back({"file:line", "stderr lacks '" + s + "'"});
  if (const std::string d = tree_difference(before, after); !d.empty())
    out.broken.push_back({"disk", "left on disk: " + d});
  return out;
}

}  // namespace lrchain::corpus
