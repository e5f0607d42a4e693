#include <simp/obs/ObjectClasses.h>
#include <simp/obs/Palette.h>

#include <cctype>

namespace simp::obs {
namespace {

/// The detector's 14 classes in defaultClassNames() order: Tableau 10, then four light Tableau 20.
constexpr std::array<Rgb, 14> kDetectorClassColors = {{{31, 119, 180},
                                                       {255, 127, 14},
                                                       {44, 160, 44},
                                                       {214, 39, 40},
                                                       {148, 103, 189},
                                                       {140, 86, 75},
                                                       {227, 119, 194},
                                                       {127, 127, 127},
                                                       {188, 189, 34},
                                                       {23, 190, 207},
                                                       {255, 187, 120},
                                                       {152, 223, 138},
                                                       {255, 152, 150},
                                                       {197, 176, 213}}};

/// FNV-1a, 32 bit: fixed by its definition, unlike std::hash.
std::uint32_t fnv1a(const std::string& s) {
    std::uint32_t h = 2166136261u;
    for (unsigned char c : s) {
        h ^= c;
        h *= 16777619u;
    }
    return h;
}

}  // namespace

std::string canonicalClassName(const std::string& name) {
    std::string out;
    for (unsigned char c : name) out.push_back(c == '_' || c == '-' ? ' ' : static_cast<char>(std::tolower(c)));
    const auto first = out.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return out.substr(first, out.find_last_not_of(" \t") - first + 1);
}

Rgb classColorRgb(const std::string& class_name) {
    static const std::vector<std::string> canonical_defaults = [] {
        std::vector<std::string> names;
        for (const auto& n : defaultClassNames()) names.push_back(canonicalClassName(n));
        return names;
    }();
    const std::string name = canonicalClassName(class_name);
    const int i = classIndexOf(canonical_defaults, name);
    if (i >= 0 && static_cast<std::size_t>(i) < kDetectorClassColors.size()) return kDetectorClassColors[static_cast<std::size_t>(i)];
    return kFallbackClassColors[fnv1a(name) % kFallbackClassColors.size()];
}

Rgb classColorRgb(int class_id, const std::vector<std::string>& class_names) {
    if (class_id >= 0 && static_cast<std::size_t>(class_id) < class_names.size())
        return classColorRgb(class_names[static_cast<std::size_t>(class_id)]);
    return classColorRgb("class " + std::to_string(class_id));
}

Rgb classColorRgb(int class_id) { return classColorRgb(class_id, defaultClassNames()); }

Rgb seriesColorRgb(std::size_t i) { return kDetectorClassColors[i % 10]; }

}  // namespace simp::obs
