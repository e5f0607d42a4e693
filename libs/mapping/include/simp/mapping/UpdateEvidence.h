#pragma once
/// \file UpdateEvidence.h
/// Per-object evidence of a map update (MapUpdate.h), written by simp-map --update to
/// M/update_evidence.tsv so that its decisions can be analysed against a truth (columns:
/// doc/formats.md "update_evidence.tsv").

#include <cstdint>
#include <string>
#include <vector>

namespace simp::mapping {

/// One object of the earlier map (`origin` "earlier") or one object this session made ("new").
struct UpdateEvidence {
    std::int64_t id = 0;          ///< its id in M0 (earlier) or the id the builder gave it (new)
    std::string origin;           ///< "earlier" | "new"
    std::string class_name;
    double x_m = 0, y_m = 0;      ///< planar box centre (earlier: in M0; new: this session's estimate)
    int windows_matched = 0;      ///< integration windows of this session that matched (or made) it
    int windows_missed = 0;       ///< windows in which it was active (expected) and unmatched
    int windows_missed_behind_new = 0;  ///< SessionEvidence::windows_missed_behind_new (earlier objects)
    double class_rate = 0;        ///< the class's match rate this session (earlier objects; 0 for new)
    double p_present = 1;         ///< binomial P(<= matched | expected, class_rate) (earlier objects)
    /// earlier: kept | unseen | merged | removed | moved | re-estimated | turned | nested;
    /// new: added | move-target | too-few-windows | twin | overlaps-earlier
    std::string decision;
    std::int64_t nearest_id = -1;  ///< nearest object of the other origin and the same class (-1: none)
    double nearest_m = -1;         ///< its planar centre distance (m; -1: none)
    int nearest_windows = 0;       ///< its matched windows this session
    double turn_deg = 0;           ///< (earlier) mean heading change over its matched windows (SessionTurn.h); 0 without
    double turn_std_error_deg = 0; ///< (earlier) standard error of turn_deg
    double turn_concentration = 0; ///< (earlier) TurnEstimate::concentration (a turn counts from kMinTurnConcentration)
};

/// Writes the rows as a tab-separated file with a header line.
/// \throw std::runtime_error naming the file when it cannot be written.
void saveUpdateEvidence(const std::vector<UpdateEvidence>& rows, const std::string& path);

}  // namespace simp::mapping
