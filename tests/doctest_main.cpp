// The doctest main shared by every module's test executable. ctest runs one test file of a module
// at a time by filtering on the source file (cmake/QmDefaults.cmake, qm_module_tests); a run whose
// filters select no test case fails here, so that a renamed or emptied file cannot pass unnoticed.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <iostream>

namespace {

// Test cases that passed the filters in the last run; none known until a run ends (queries such
// as --help and --list-test-cases end no run).
int selected_test_cases = -1;

struct Selection : doctest::IReporter {
    explicit Selection(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats& s) override { selected_test_cases = static_cast<int>(s.numTestCasesPassingFilters); }
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

}  // namespace

REGISTER_LISTENER("selection", 1, Selection);

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    const int result = context.run();
    if (context.shouldExit()) return result;
    if (selected_test_cases == 0) {
        std::cerr << "error: the filters selected no test case\n";
        return 1;
    }
    return result;
}
