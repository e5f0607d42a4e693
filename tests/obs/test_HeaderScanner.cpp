/// HeaderScanner finds, window after sliding window, the same headers as scanning each window anew.
#include <gtest/gtest.h>
#include <simp/obs/HeaderScanner.h>

#include <random>
#include <set>
#include <tuple>

namespace {

using Set = std::set<std::tuple<std::size_t, std::size_t, std::uint32_t>>;

Set asSet(const std::vector<simp::obs::HeaderAt>& v) {
    Set s;
    for (const auto& h : v) s.insert({h.prefix, h.data, h.version});
    return s;
}

TEST(HeaderScanner, SlidingWindowsFindWhatAFreshScanFinds) {
    // Random bytes with headers of both formats (and namespaced names) planted every few hundred bytes.
    std::mt19937 rng(7);
    std::vector<std::uint8_t> file(200000);
    for (auto& c : file) c = static_cast<std::uint8_t>(rng() & 0xff);
    const std::string names[] = {"CSensoryFrame", "mrpt::obs::CSensoryFrame", "x::CSensoryFrame"};
    std::size_t planted = 0;
    for (std::size_t at = 10; at + 64 < file.size(); at += 150 + rng() % 400, ++planted) {
        const std::string& n = names[planted % 3];
        std::size_t p = at;
        if (planted % 2) {
            file[p++] = static_cast<std::uint8_t>(0x80 | n.size());
        } else {
            file[p++] = static_cast<std::uint8_t>(n.size());
            file[p++] = 0, file[p++] = 0, file[p++] = 0;
        }
        for (char ch : n) file[p++] = static_cast<std::uint8_t>(ch);
    }
    simp::obs::HeaderScanner scanner("CSensoryFrame");
    const std::size_t window = 4096;
    std::size_t checked = 0, found = 0;
    for (std::size_t base = 0; base < file.size(); base += 1 + rng() % 700) {
        const std::vector<std::uint8_t> b(file.begin() + static_cast<std::ptrdiff_t>(base),
                                          file.begin() + static_cast<std::ptrdiff_t>(std::min(file.size(), base + window)));
        const auto fresh = asSet(simp::obs::headersOf(b.data(), b.size(), "CSensoryFrame"));
        ASSERT_EQ(asSet(scanner.headersIn(b, base)), fresh) << "window at " << base;
        ++checked;
        found += fresh.size();
    }
    EXPECT_GT(checked, 300u);
    EXPECT_GT(found, 5000u);  // the windows did hold headers, many cut by their ends
    // A window that does not continue the last one (jumps back) is scanned whole.
    const std::vector<std::uint8_t> b(file.begin(), file.begin() + window);
    EXPECT_EQ(asSet(scanner.headersIn(b, 0)), asSet(simp::obs::headersOf(b.data(), b.size(), "CSensoryFrame")));
}

}  // namespace
