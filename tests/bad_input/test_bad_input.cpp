/// The data-driven bad-input table of issue #14 (doc/bad-input.md): every row of cases.tsv runs one
/// app as a real process on files it creates, with a 60 s timeout, and must end with the expected
/// non-zero exit code (never a signal: an abort, a segfault, a sanitizer report, a kill on timeout)
/// and print the expected message fragment.
#include <gtest/gtest.h>

#include "BadInputCase.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using namespace simp_bad_input;

namespace {

/// Fixtures the cases refer to as $W (a world), $Q (a sequence directory), $R (a small rawlog),
/// $D (tests/data), made once with the project's own apps (tiny: 2 rooms, 4 s).
Variables makeFixtures(const fs::path& root) {
    const std::string bin = std::string(SIMP_BINARY_DIR) + "/bin/";
    fs::create_directories(root);
    Variables v;
    v["W"] = (root / "world").string();
    v["Q"] = (root / "seq").string();
    v["R"] = (root / "example.rawlog").string();
    v["D"] = std::string(SIMP_SOURCE_DIR) + "/tests/data";
    v["SRC"] = SIMP_SOURCE_DIR;
    v["BIN"] = bin;
    const auto make = [&](const std::vector<std::string>& argv) {
        const RunResult r = runProcess(argv, root / "fixture.log", 300);
        if (!r.exited || r.code != 0) {
            std::ifstream f(root / "fixture.log");
            std::stringstream s;
            s << f.rdbuf();
            throw std::runtime_error("fixture command failed: " + argv[0] + "\n" + s.str());
        }
    };
    if (!fs::exists(v["W"] + "/objects.json"))
        make({bin + "simp-sim", "world", "--builtin", "office", "--seed", "1", "--rooms", "2", "--out", v["W"]});
    if (!fs::exists(v["Q"] + "/sequence.rawlog"))
        make({bin + "simp-sim", "sequence", "--world", v["W"], "--seed", "1", "--duration", "4", "--out", v["Q"]});
    if (!fs::exists(v["R"])) make({bin + "simp-example-rawlog", "--out", v["R"], "--frames", "3"});
    return v;
}

}  // namespace

TEST(BadInput, EveryCaseOfTheTableFailsCleanly) {
    const fs::path table = fs::path(SIMP_SOURCE_DIR) / "tests/bad_input/cases.tsv";
    const std::vector<Case> cases = readCases(table.string());
    ASSERT_GE(cases.size(), 250u) << "the table must keep at least 250 cases (issue #14)";
    const fs::path root = fs::path(SIMP_TEST_OUTPUT_DIR) / "bad_input";
    fs::create_directories(root);
    const Variables vars = makeFixtures(root / "fixtures");

    // Two workers: the table's processes are tiny and mostly start-up time.
    std::vector<Outcome> outcomes(cases.size());
    std::atomic<std::size_t> next{0};
    const auto t0 = std::chrono::steady_clock::now();
    auto worker = [&] {
        for (std::size_t i = next++; i < cases.size(); i = next++) outcomes[i] = runCase(cases[i], root / "cases", vars);
    };
    std::thread a(worker), b(worker);
    a.join();
    b.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::size_t passed = 0;
    std::map<std::string, std::size_t> per_app;
    std::ofstream summary(root / "summary.txt");
    for (std::size_t i = 0; i < cases.size(); ++i) {
        ++per_app[cases[i].app];
        if (outcomes[i].ok) {
            ++passed;
            continue;
        }
        ADD_FAILURE() << table.string() << ":" << cases[i].line << ": " << cases[i].app << " " << cases[i].args
                      << "\n  " << outcomes[i].problem << "\n  output: " << outcomes[i].output.substr(0, 2000);
        summary << "FAIL line " << cases[i].line << ": " << outcomes[i].problem << "\n";
    }
    summary << passed << " of " << cases.size() << " cases passed in " << seconds << " s\n";
    std::vector<std::size_t> order(cases.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return outcomes[x].seconds > outcomes[y].seconds; });
    summary << "slowest cases:\n";
    for (std::size_t k = 0; k < std::min<std::size_t>(15, order.size()); ++k)
        summary << "  line " << cases[order[k]].line << ": " << outcomes[order[k]].seconds << " s " << cases[order[k]].app << "\n";
    for (const auto& [app, n] : per_app) summary << app << ": " << n << " cases\n";
    std::cout << "[bad-input] " << passed << " of " << cases.size() << " cases passed in " << seconds << " s ("
              << per_app.size() << " apps); details in " << (root / "summary.txt").string() << "\n";
}
