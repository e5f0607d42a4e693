#include <simp/eval/BatchMaps.h>
#include <simp/eval/Report.h>
#include <simp/world/World.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace simp::eval {
namespace {

/// Loads a world directory; errors name the .ini key the directory came from.
world::World loadListed(const std::string& dir, const std::string& key, const std::string& map_name) {
    const std::string where = "batch: " + key + " (map '" + map_name + "'): '" + dir + "'";
    if (!fs::is_directory(dir)) throw std::runtime_error(where + ": directory not found");
    try {
        return world::loadWorld(dir);
    } catch (const std::exception& e) {
        throw std::runtime_error(where + ": not a world directory: " + e.what());
    }
}

}  // namespace

std::vector<BatchMapResult> evaluateBatchMaps(const BatchConfig& cfg) {
    const std::string gt_key = cfg.map_ground_truths.empty() ? "[batch] world" : "[batch] map_ground_truths";
    std::vector<BatchMapResult> out;
    for (const auto& m : cfg.batchMaps()) {
        const world::World map = loadListed(m.dir, "[batch] maps", m.name);
        const world::World gt = loadListed(m.ground_truth, gt_key, m.name);
        try {
            out.push_back({m, evaluateMap(gt.objects, map.objects, cfg.map_metrics)});
        } catch (const std::exception& e) {
            throw std::runtime_error("batch: [batch] maps (map '" + m.name + "'): '" + m.dir + "' vs ground truth '" +
                                     m.ground_truth + "': " + e.what());
        }
    }
    return out;
}

std::string batchMapsMarkdown(const std::vector<BatchMapResult>& maps) {
    if (maps.empty()) return {};
    std::ostringstream o;
    o << "## Map quality (Table I)\n\n| Map | IoU | Pr | Rc |\n|---|---:|---:|---:|\n";
    for (const auto& r : maps)
        o << "| " << r.map.name << " | " << fmt(r.metrics.iou, 2) << " | " << fmt(r.metrics.precision, 2) << " | "
          << fmt(r.metrics.recall, 2) << " |\n";
    o << "\n";
    for (const auto& r : maps)
        o << "### " << r.map.name << ": `" << r.map.dir << "` vs `" << r.map.ground_truth << "`\n\n"
          << mapMarkdownTable(r.metrics) << "\n";
    return o.str();
}

std::string batchMapsCsv(const std::vector<BatchMapResult>& maps) {
    std::ostringstream o;
    o << "map,class,n_gt,n_pred,n_matched,iou,precision,recall,iou_3d,dir,ground_truth\n";
    const auto line = [&](const BatchMapResult& r, const std::string& cls, std::size_t gt, std::size_t pred,
                          std::size_t matched, double iou, double pr, double rc, double iou3d) {
        o << r.map.name << ",\"" << cls << "\"," << gt << "," << pred << "," << matched << "," << fmt(iou, 6) << ","
          << fmt(pr, 6) << "," << fmt(rc, 6) << "," << fmt(iou3d, 6) << "," << r.map.dir << "," << r.map.ground_truth
          << "\n";
    };
    for (const auto& r : maps) {
        std::size_t gt = 0, pred = 0, matched = 0;
        for (const auto& [name, c] : r.metrics.per_class) {
            line(r, name, c.n_gt, c.n_pred, c.n_matched, c.iou, c.precision, c.recall, c.iou_3d);
            gt += c.n_gt, pred += c.n_pred, matched += c.n_matched;
        }
        const auto& m = r.metrics;
        line(r, "AVG", gt, pred, matched, m.iou, m.precision, m.recall, m.iou_3d);
    }
    return o.str();
}

}  // namespace simp::eval
