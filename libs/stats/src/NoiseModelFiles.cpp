/// \file NoiseModelFiles.cpp
#include <simp/stats/NoiseModelFiles.h>
#include <simp/world/ObjectMapData.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace simp::stats {

namespace {

std::ofstream openOut(const std::string& path) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    return out;
}

}  // namespace

void writeClassNoiseJson(const std::string& path, const std::vector<std::string>& class_names,
                         const std::vector<std::optional<NoiseFit>>& fits) {
    world::ObjectMapData d;
    d.class_names = class_names;
    d.class_noise.assign(class_names.size(), std::nullopt);
    for (std::size_t c = 0; c < fits.size() && c < class_names.size(); ++c)
        if (fits[c]) d.class_noise[c] = fits[c]->model;
    world::saveObjectMap(d, path);  // validates and writes with full precision
}

void writeClassNoiseCsv(const std::string& path, const std::vector<std::optional<NoiseFit>>& fits,
                        double resolution_m) {
    std::ofstream out = openOut(path);
    out << "category,mx,my,sx,sy,b\n";
    for (std::size_t c = 0; c < fits.size(); ++c) {
        out << c;
        if (fits[c]) {
            const model::NoiseModel& m = fits[c]->model;
            out << ',' << m.mean_m.x() / resolution_m << ',' << m.mean_m.y() / resolution_m << ','
                << std::sqrt(m.cov_m2(0, 0)) / resolution_m << ',' << std::sqrt(m.cov_m2(1, 1)) / resolution_m
                << ',' << m.exponent_b << '\n';
        } else {
            out << ",,,,,\n";
        }
    }
    if (!out) throw std::runtime_error(path + ": write failed");
}

void writeClassNoiseStatsCsv(const std::string& path, const std::vector<std::string>& class_names,
                             const std::vector<std::optional<NoiseFit>>& fits) {
    std::ofstream out = openOut(path);
    out << "class,n,rejected,mu_x_m,mu_y_m,cov_xx_m2,cov_xy_m2,cov_yy_m2,se_mu_x_m,se_mu_y_m,se_cov_xx_m2,"
           "se_cov_xy_m2,se_cov_yy_m2\n";
    for (std::size_t c = 0; c < fits.size() && c < class_names.size(); ++c) {
        if (!fits[c]) continue;
        const NoiseFit& f = *fits[c];
        out << '"' << class_names[c] << '"' << ',' << f.n << ',' << f.rejected << ',' << f.model.mean_m.x() << ','
            << f.model.mean_m.y() << ',' << f.model.cov_m2(0, 0) << ',' << f.model.cov_m2(0, 1) << ','
            << f.model.cov_m2(1, 1) << ',' << f.se_mean_m.x() << ',' << f.se_mean_m.y() << ',' << f.se_cov_m2(0, 0)
            << ',' << f.se_cov_m2(0, 1) << ',' << f.se_cov_m2(1, 1) << '\n';
    }
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace simp::stats
