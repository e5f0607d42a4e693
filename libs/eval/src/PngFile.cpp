#include <opencv2/imgcodecs.hpp>
#include <simp/eval/PngFile.h>

#include <filesystem>
#include <stdexcept>

namespace simp::eval {

void writePng(const std::string& path, const cv::Mat& image) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    bool ok = false;
    try {
        ok = cv::imwrite(path, image);
    } catch (const cv::Exception& e) {
        throw std::runtime_error("cannot write image '" + path + "': " + e.what());
    }
    if (!ok) throw std::runtime_error("cannot write image '" + path + "' (is the extension .png?)");
}

}  // namespace simp::eval
