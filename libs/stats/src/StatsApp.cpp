/// \file StatsApp.cpp
#include <simp/io/StrictIni.h>
#include <simp/io/CommandLine.h>
#include <simp/stats/NoiseModelFiles.h>
#include <simp/stats/NoisePlot.h>
#include <simp/stats/StatsApp.h>
#include <simp/world/World.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace simp::stats {

namespace fs = std::filesystem;

io::CommandLine StatsApp::commandLine() {
    io::CommandLine c("simp-stats",
                      "Fits the per-class detection noise N(mu, Sigma) in the object frame (paper Sec. Statistical\n"
                      "Analysis) and writes DIR/class_noise.json, class_noise.csv, class_noise_stats.csv, noise_<class>.png.");
    c.required("rawlog", "Q/sequence.rawlog", "detections (CObservationObjects3D) with timestamps")
        .required("poses", "Q/groundtruth.tum", "ground-truth robot poses (TUM), interpolated at each observation's time")
        .required("world", "W", "world directory (or an objects.json file) with the ground-truth objects")
        .required("out", "DIR", "output directory")
        .option("delta", "M", "matching gate: max centre distance, overrides [simp-stats] delta_m")
        .unit("m")
        .option("config", "INI", ".ini with a [simp-stats] section (doc/statistics.md)");
    return c;
}

std::string StatsApp::usage() { return commandLine().help(); }

bool StatsApp::initialize(int argc, const char* const* argv, std::ostream& out) {
    io::CommandLine a = commandLine();
    if (!a.parse(argc, argv, out)) return false;
    rawlog_path = a.value("rawlog"), poses_path = a.value("poses"), world_path = a.value("world"), out_dir = a.value("out");
    config_path = a.value("config");
    const std::optional<double> delta = a.number("delta", 1e-6, 100);
    if (!config_path.empty())
        io::StrictIni(config_path).loadChecked([&](const io::StrictIni& ini) { options.loadFromConfigFile(ini, "simp-stats"); });
    if (delta) options.delta_m = *delta;
    options.validate();
    return true;
}

int StatsApp::run(std::ostream& out) {
    options.dumpToTextStream(out);
    const world::ObjectMapData gt = fs::is_directory(world_path) ? world::loadWorld(world_path).objects
                                                                 : world::loadObjectMap(world_path);
    if (gt.objects.empty()) throw std::runtime_error(world_path + ": the world has no objects to match against");
    const auto poses = io::readTum(poses_path);
    if (poses.size() < 2) throw std::runtime_error(poses_path + ": need at least 2 poses");
    out << "reading " << rawlog_path << " ...\n";
    const auto frames = obs::readRawlog(rawlog_path);
    out << frames.size() << " frames\n";
    samples = collectOffsetSamples(frames, poses, gt, SampleOptions{options.delta_m, options.min_confidence});
    const SampleCounts& n = samples.counts;
    out << "detections " << n.detections << ": matched " << n.matched << ", discarded (none within delta) "
        << n.discarded << ", no pose " << n.no_pose << ", unknown class " << n.unknown_class << ", low score "
        << n.low_confidence << "\n";

    class_names = gt.class_names;
    fits.assign(class_names.size(), std::nullopt);
    fs::create_directories(out_dir);
    for (std::size_t c = 0; c < class_names.size(); ++c) {
        const auto& s = samples.per_class[c];
        if (s.size() < static_cast<std::size_t>(options.min_samples)) {
            if (!s.empty()) out << class_names[c] << ": " << s.size() << " samples < min_samples, not modelled\n";
            continue;
        }
        NoiseFit f = fitGaussian(s, options.outlier_mahalanobis);
        const double sigma_max = std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(f.model.cov_m2).eigenvalues()(1));
        const double half = options.plot_half_extent_m > 0 ? options.plot_half_extent_m : std::max(0.5, 4.0 * sigma_max);
        const Histogram2D h = makeHistogram(s, options.cell_size_m, f.model.mean_m, half);
        if (options.fit_source == "histogram") f = fitGaussianFromHistogram(h);
        std::string file = class_names[c];
        std::replace(file.begin(), file.end(), ' ', '_');
        writeNoisePng((fs::path(out_dir) / ("noise_" + file + ".png")).string(), h, f,
                      class_names[c] + " n=" + std::to_string(f.n), options.plot_pixels_per_cell);
        out << class_names[c] << ": n=" << f.n << " mu=(" << f.model.mean_m.x() << ", " << f.model.mean_m.y()
            << ") m, sigma=(" << std::sqrt(f.model.cov_m2(0, 0)) << ", " << std::sqrt(f.model.cov_m2(1, 1))
            << ") m, rho=" << f.model.cov_m2(0, 1) / std::sqrt(f.model.cov_m2(0, 0) * f.model.cov_m2(1, 1)) << "\n";
        fits[c] = f;
    }
    writeClassNoiseJson((fs::path(out_dir) / "class_noise.json").string(), class_names, fits);
    writeClassNoiseCsv((fs::path(out_dir) / "class_noise.csv").string(), fits, options.cell_size_m);
    writeClassNoiseStatsCsv((fs::path(out_dir) / "class_noise_stats.csv").string(), class_names, fits);
    out << "wrote " << out_dir << "/class_noise.json, class_noise.csv, class_noise_stats.csv\n";
    return 0;
}

}  // namespace simp::stats
