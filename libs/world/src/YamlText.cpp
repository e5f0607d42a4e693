/// \file YamlText.cpp
#include <simp/world/YamlText.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace simp::world {
namespace {

[[noreturn]] void failAtLine(const std::string& path, std::size_t line, const std::string& what) {
    throw std::runtime_error(path + ": line " + std::to_string(line) + ": " + what);
}

std::string hexByte(unsigned char c) {
    static const char* digits = "0123456789ABCDEF";
    return std::string("0x") + digits[c >> 4] + digits[c & 15];
}

/// Length of the UTF-8 sequence starting at s[i] (1-4), or 0 when it is not valid UTF-8
/// (overlong forms, surrogates and code points above U+10FFFF are invalid).
std::size_t utf8Length(const std::string& s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = b(i);
    if (c < 0x80) return 1;
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if (c >= 0xC2 && c <= 0xDF) n = 2, cp = c & 0x1F;
    else if (c >= 0xE0 && c <= 0xEF) n = 3, cp = c & 0x0F;
    else if (c >= 0xF0 && c <= 0xF4) n = 4, cp = c & 0x07;
    else return 0;
    if (i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((b(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (b(i + k) & 0x3F);
    }
    if ((n == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)))
        return 0;
    return n;
}

}  // namespace

std::string readYamlText(const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw std::runtime_error(path + ": cannot read (" + ec.message() + ")");
    if (size > kMaxYamlBytes)
        throw std::runtime_error(path + ": " + std::to_string(size) + " bytes, more than the " +
                                 std::to_string(kMaxYamlBytes) + " a floor-plan YAML file may have");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buf;
    buf << in.rdbuf();
    if (!in && !in.eof()) throw std::runtime_error(path + ": cannot read");
    const std::string text = buf.str();
    std::size_t line = 1;
    bool line_start = true;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (line_start && c == '%')
            failAtLine(path, line, "YAML directives ('%...') are not accepted in a floor-plan file");
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
            failAtLine(path, line, "control character " + hexByte(c) + " (YAML text is printable characters)");
        if (c == 0x7F) failAtLine(path, line, "control character 0x7F (YAML text is printable characters)");
        const std::size_t n = utf8Length(text, i);
        if (n == 0) failAtLine(path, line, "byte " + hexByte(c) + " is not UTF-8 (YAML text must be UTF-8)");
        line_start = c == '\n';
        if (c == '\n') ++line;
        i += n;
    }
    return text;
}

}  // namespace simp::world
