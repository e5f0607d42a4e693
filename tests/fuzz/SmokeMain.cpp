// Mutation smoke of a fuzz target without libFuzzer (the normal gcc build, CTest): every file of a
// seed corpus folder, then a fixed number of deterministic mutations of each (bit flips, byte
// overwrites, extreme 32-bit counts, truncations, duplicated and inserted chunks) go through the
// target's LLVMFuzzerTestOneInput. No coverage feedback: a regression net over the readers in
// every CI run; the coverage-guided runs are the clang build of doc/fuzzing.md. A crash, a hang
// (CTest's timeout), an uncaught exception (std::bad_alloc included) or a peak RSS beyond
// --max-rss-mb fails the test. Same corpus and seed, same inputs.
//   fuzz_<target>_smoke CORPUS_DIR [--mutations N] [--seed S] [--max-rss-mb M] [--save-input PATH]
// (--save-input: every input is written to PATH before it runs, so a killed run leaves its culprit there.)
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

void mutate(Bytes& b, std::mt19937_64& rng) {
    auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % std::max<std::size_t>(n, 1)); };
    const int kind = static_cast<int>(rng() % 7);
    if (b.empty() && kind != 6) {
        b.push_back(static_cast<std::uint8_t>(rng()));
        return;
    }
    switch (kind) {
        case 0: b[pick(b.size())] ^= static_cast<std::uint8_t>(1u << (rng() % 8)); break;  // bit flip
        case 1: b[pick(b.size())] = static_cast<std::uint8_t>(rng()); break;               // random byte
        case 2: {  // an extreme little-endian 32-bit value (counts, lengths, sizes)
            static const std::uint32_t extremes[] = {0u, 1u, 0x7fffffffu, 0x80000000u, 0xffffffffu, 0x10000u};
            const std::uint32_t v = extremes[rng() % 6];
            const std::size_t at = pick(b.size());
            for (std::size_t k = 0; k < 4 && at + k < b.size(); ++k) b[at + k] = static_cast<std::uint8_t>(v >> (8 * k));
            break;
        }
        case 3: b.resize(pick(b.size())); break;  // truncation
        case 4: {                                 // a chunk duplicated in place
            const std::size_t from = pick(b.size()), len = std::min<std::size_t>(pick(64) + 1, b.size() - from);
            const Bytes chunk(b.begin() + static_cast<std::ptrdiff_t>(from), b.begin() + static_cast<std::ptrdiff_t>(from + len));
            b.insert(b.begin() + static_cast<std::ptrdiff_t>(pick(b.size())), chunk.begin(), chunk.end());
            break;
        }
        case 5: {  // random bytes inserted
            const std::size_t at = pick(b.size() + 1), len = pick(16) + 1;
            for (std::size_t k = 0; k < len; ++k) b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), static_cast<std::uint8_t>(rng()));
            break;
        }
        default: {  // ASCII digits overwritten (text formats: numbers out of range)
            static const char* texts[] = {"1e308", "-1", "nan", "99999999999", "0", "inf"};
            const char* t = texts[rng() % 6];
            const std::size_t at = pick(b.size() + 1);
            b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), t, t + std::strlen(t));
            break;
        }
    }
}

long peakRssMb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024;  // ru_maxrss is in KiB on Linux
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " CORPUS_DIR [--mutations N] [--seed S] [--max-rss-mb M]\n";
        return 2;
    }
    const std::filesystem::path corpus = argv[1];
    std::size_t mutations = 300;
    std::uint64_t seed = 1;
    long max_rss_mb = 0;  // 0: not checked
    std::string save_input;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string a = argv[i], v = argv[i + 1];
        if (a == "--mutations") mutations = std::stoul(v);
        else if (a == "--seed") seed = std::stoull(v);
        else if (a == "--max-rss-mb") max_rss_mb = std::stol(v);
        else if (a == "--save-input") save_input = v;
        else {
            std::cerr << "unknown option '" << a << "'\n";
            return 2;
        }
    }
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(corpus))
        for (const auto& e : std::filesystem::directory_iterator(corpus))
            if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) {
        std::cerr << "no seed files in '" << corpus.string() << "'\n";
        return 2;
    }
    std::size_t runs = 0, largest = 0;
    const auto runOne = [&](const Bytes& b) {
        if (!save_input.empty()) std::ofstream(save_input, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
        LLVMFuzzerTestOneInput(b.data(), b.size());
        ++runs;
    };
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        const Bytes seed_bytes((std::istreambuf_iterator<char>(in)), {});
        std::mt19937_64 rng(seed ^ std::hash<std::string>{}(f.filename().string()));
        runOne(seed_bytes);
        for (std::size_t m = 0; m < mutations; ++m) {
            Bytes b = seed_bytes;
            const int stacked = 1 + static_cast<int>(rng() % 4);
            for (int k = 0; k < stacked; ++k) mutate(b, rng);
            largest = std::max(largest, b.size());
            runOne(b);
        }
    }
    std::error_code ec;  // the targets' scratch folder (FuzzUtil.h)
    std::filesystem::remove_all(std::filesystem::temp_directory_path() / ("simp_fuzz_" + std::to_string(::getpid())), ec);
    const long rss = peakRssMb();
    std::cout << runs << " inputs (" << files.size() << " seeds, largest " << largest << " bytes), peak RSS " << rss
              << " MB\n";
    if (max_rss_mb > 0 && rss > max_rss_mb) {
        std::cerr << "peak RSS " << rss << " MB exceeds --max-rss-mb " << max_rss_mb << "\n";
        return 1;
    }
    return 0;
}
