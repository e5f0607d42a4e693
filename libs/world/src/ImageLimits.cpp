#include <simp/world/ImageLimits.h>

#include <array>
#include <cctype>
#include <fstream>
#include <stdexcept>

namespace simp::world {
namespace {

std::uint32_t bigEndian32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

/// Next whitespace-separated token of a PNM header, skipping '#' comments.
bool pnmToken(std::istream& in, std::string& tok) {
    tok.clear();
    char c;
    while (in.get(c)) {
        if (c == '#') {
            std::string comment;
            std::getline(in, comment);
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            tok += c;
            break;
        }
    }
    while (in.get(c) && !std::isspace(static_cast<unsigned char>(c)) && tok.size() < 20) tok += c;
    return !tok.empty();
}

std::optional<std::uint64_t> pnmNumber(std::istream& in) {
    std::string tok;
    if (!pnmToken(in, tok) || tok.size() > 19) return std::nullopt;
    for (char c : tok)
        if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    return std::stoull(tok);
}

}  // namespace

std::optional<ImageSize> declaredImageSize(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::array<unsigned char, 24> h{};
    in.read(reinterpret_cast<char*>(h.data()), h.size());
    const auto got = static_cast<std::size_t>(in.gcount());
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (got >= 24 && std::equal(kPng, kPng + 8, h.begin()))  // IHDR: width, height at 16, 20
        return ImageSize{bigEndian32(&h[16]), bigEndian32(&h[20])};
    if (got >= 2 && h[0] == 'P' && h[1] >= '1' && h[1] <= '6') {
        in.clear();
        in.seekg(2);
        const auto w = pnmNumber(in), hgt = pnmNumber(in);
        if (w && hgt) return ImageSize{*w, *hgt};
    }
    return std::nullopt;
}

void checkRasterSize(const std::string& path, const ImageSize& s) {
    // Compare without multiplying: both sides may be up to 2^64.
    if (s.width != 0 && s.height > kMaxRasterPixels / s.width)
        throw std::runtime_error(path + ": image of " + std::to_string(s.width) + " x " + std::to_string(s.height) +
                                 " px exceeds the maximum of " + std::to_string(kMaxRasterPixels) +
                                 " pixels (doc/formats.md)");
}

void checkDeclaredRasterSize(const std::string& path) {
    if (const auto s = declaredImageSize(path)) checkRasterSize(path, *s);
}

}  // namespace simp::world
