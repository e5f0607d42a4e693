#pragma once
/// \file BatchMaps.h
/// The map half of a batch: every built map of `[batch] maps` evaluated against its ground-truth
/// world with evaluateMap (the metrics of `simp-eval map`, paper Table I), as Markdown and CSV.

#include <simp/eval/BatchConfig.h>
#include <simp/eval/MapMetrics.h>

#include <string>
#include <vector>

namespace simp::eval {

struct BatchMapResult {
    BatchMap map;
    MapMetrics metrics;
};

/// Loads and evaluates every map of cfg.batchMaps() with cfg.map_metrics, in order.
/// \throw std::runtime_error naming the .ini key ([batch] maps, map_ground_truths or world) and
///        the directory when one is missing or cannot be loaded or evaluated.
std::vector<BatchMapResult> evaluateBatchMaps(const BatchConfig& cfg);

/// "## Map quality (Table I)": one line per map (AVG IoU, Pr, Rc), then per map the table of
/// `simp-eval map` (classes as columns, AVG last). Empty when there is no map.
std::string batchMapsMarkdown(const std::vector<BatchMapResult>& maps);

/// CSV: map,class,n_gt,n_pred,n_matched,iou,precision,recall,iou_3d,dir,ground_truth; one line per
/// map and class, then the map's AVG line (counts summed, metrics the class means).
std::string batchMapsCsv(const std::vector<BatchMapResult>& maps);

}  // namespace simp::eval
