#include <simp/eval/MapMetrics.h>
#include <simp/geometry/Box3DIoU.h>
#include <simp/geometry/Footprint.h>
#include <simp/geometry/Hungarian.h>

#include <Eigen/Core>
#include <algorithm>
#include <stdexcept>

namespace simp::eval {
namespace {

/// Object indices of each class name, after checking every object of the map.
std::map<std::string, std::vector<std::size_t>> objectsByClass(const world::ObjectMapData& map,
                                                                const char* which) {
    std::map<std::string, std::vector<std::size_t>> out;
    for (std::size_t i = 0; i < map.objects.size(); ++i) {
        const auto& o = map.objects[i];
        if (o.class_id < 0 || o.class_id >= static_cast<int>(map.class_names.size()))
            throw std::invalid_argument(std::string(which) + " map: object " + std::to_string(i) + " (id " +
                                        std::to_string(o.id) + ") has class id " + std::to_string(o.class_id) +
                                        " outside the class list (" + std::to_string(map.class_names.size()) +
                                        " classes)");
        if (!o.box.isValid(1e-6))
            throw std::invalid_argument(std::string(which) + " map: object " + std::to_string(i) + " (id " +
                                        std::to_string(o.id) + ") has an invalid box (NaN, size <= 0 or not a rotation)");
        out[map.class_names[o.class_id]].push_back(i);
    }
    return out;
}

}  // namespace

MapMetrics evaluateMap(const world::ObjectMapData& ground_truth, const world::ObjectMapData& predicted,
                       const MapMatchParams& params) {
    auto gt_by_class = objectsByClass(ground_truth, "ground-truth");
    auto pred_by_class = objectsByClass(predicted, "predicted");
    if (!params.classes.empty()) {
        const auto keepOnlySelected = [&](std::map<std::string, std::vector<std::size_t>>& by_class) {
            for (auto it = by_class.begin(); it != by_class.end();)
                it = std::find(params.classes.begin(), params.classes.end(), it->first) == params.classes.end()
                         ? by_class.erase(it)
                         : std::next(it);
        };
        keepOnlySelected(gt_by_class);
        keepOnlySelected(pred_by_class);
    }
    if (gt_by_class.empty() && pred_by_class.empty())
        throw std::invalid_argument("map evaluation: neither the ground-truth nor the predicted map has objects");

    std::map<std::string, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> classes;
    for (const auto& [name, idx] : gt_by_class) classes[name].first = idx;
    for (const auto& [name, idx] : pred_by_class) classes[name].second = idx;

    MapMetrics m;
    for (const auto& [name, members] : classes) {
        const auto& [gts, preds] = members;
        ClassMapMetrics c;
        c.n_gt = gts.size();
        c.n_pred = preds.size();
        std::vector<char> gt_used(gts.size(), 0), pred_used(preds.size(), 0);
        if (!gts.empty() && !preds.empty()) {
            // Cost 1 - IoU_fp, rows = predictions, columns = ground truth. An inadmissible pair
            // costs more than any sum of admissible costs (each < 1), so the assignment first
            // maximises the number of admissible matches, then minimises sum(1 - IoU_fp).
            const double forbidden = 1.0 + static_cast<double>(std::min(preds.size(), gts.size()));
            Eigen::MatrixXd cost(preds.size(), gts.size());
            Eigen::MatrixXd iou_fp(preds.size(), gts.size()), dist(preds.size(), gts.size());
            for (std::size_t r = 0; r < preds.size(); ++r) {
                const auto& pb = predicted.objects[preds[r]].box;
                const auto pf = geometry::footprint(pb);
                for (std::size_t k = 0; k < gts.size(); ++k) {
                    const auto& gb = ground_truth.objects[gts[k]].box;
                    iou_fp(r, k) = geometry::iou(pf, geometry::footprint(gb));
                    dist(r, k) = (pb.center.head<2>() - gb.center.head<2>()).norm();
                    const bool admissible = iou_fp(r, k) > 0 && dist(r, k) <= params.max_center_dist_m;
                    cost(r, k) = admissible ? 1.0 - iou_fp(r, k) : forbidden;
                }
            }
            const auto assignment = geometry::solveAssignment(cost);
            double sum_iou = 0, sum_iou3 = 0;
            for (std::size_t r = 0; r < preds.size(); ++r) {
                const int k = assignment[r];
                if (k < 0 || cost(r, k) >= forbidden) continue;
                ObjectMatch match;
                match.pred_index = preds[r];
                match.gt_index = gts[k];
                match.iou_footprint = iou_fp(r, k);
                match.iou_3d = geometry::iou3D(predicted.objects[preds[r]].box, ground_truth.objects[gts[k]].box);
                match.center_dist_m = dist(r, k);
                m.matches.push_back(match);
                pred_used[r] = gt_used[k] = 1;
                sum_iou += match.iou_footprint;
                sum_iou3 += match.iou_3d;
                ++c.n_matched;
            }
            if (c.n_matched > 0) {
                c.iou = sum_iou / static_cast<double>(c.n_matched);
                c.iou_3d = sum_iou3 / static_cast<double>(c.n_matched);
            }
        }
        c.precision = c.n_pred ? static_cast<double>(c.n_matched) / static_cast<double>(c.n_pred) : 0.0;
        c.recall = c.n_gt ? static_cast<double>(c.n_matched) / static_cast<double>(c.n_gt) : 0.0;
        for (std::size_t k = 0; k < gts.size(); ++k)
            if (!gt_used[k]) m.missed_gt.push_back(gts[k]);
        for (std::size_t r = 0; r < preds.size(); ++r)
            if (!pred_used[r]) m.false_pred.push_back(preds[r]);
        m.per_class[name] = c;
    }
    for (const auto& [name, c] : m.per_class) {
        m.iou += c.iou;
        m.iou_3d += c.iou_3d;
        m.precision += c.precision;
        m.recall += c.recall;
    }
    const double n = static_cast<double>(m.per_class.size());
    m.iou /= n;
    m.iou_3d /= n;
    m.precision /= n;
    m.recall /= n;
    return m;
}

}  // namespace simp::eval
