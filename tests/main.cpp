// doctest entry point shared by all test executables. A run given a --test-case filter that
// selects no test case fails: CTest runs each discovered test case by name, and a name the filter
// cannot match (CMake splits discovered names at ';') must not pass silently without running.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <string_view>

namespace {

int test_cases_started = 0;

// Counts the test cases that ran (the listener sees every test case start, whatever the reporter).
struct TestCaseCounter : doctest::IReporter {
  explicit TestCaseCounter(const doctest::ContextOptions&) {}
  void report_query(const doctest::QueryData&) override {}
  void test_run_start() override {}
  void test_run_end(const doctest::TestRunStats&) override {}
  void test_case_start(const doctest::TestCaseData&) override { ++test_cases_started; }
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
  void test_case_skipped(const doctest::TestCaseData&) override {}
};
REGISTER_LISTENER("test_case_counter", 1, TestCaseCounter);

}  // namespace

int main(int argc, char** argv) {
  doctest::Context context(argc, argv);
  const int status = context.run();
  if (context.shouldExit()) return status;  // --help, --list-test-cases, ...
  bool filtered = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg(argv[i]);
    filtered |= arg.starts_with("--test-case=") || arg.starts_with("-tc=");
  }
  if (status == 0 && filtered && test_cases_started == 0) {
    std::fprintf(stderr, "no test case matched the --test-case filter (a ';' in a test name?)\n");
    return 1;
  }
  return status;
}
