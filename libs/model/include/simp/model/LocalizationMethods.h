#pragma once
/// \file LocalizationMethods.h
/// The localization methods, declared once: the paper's 3D-object sensor model, its three baselines
/// (Sec. "Baseline Comparisons") and the 2D LiDAR ones (doc/lidar.md). `simp-localize --method` and
/// `[LocalizationExperiment] sensor_model`, `[<prefix>_likelihoodOpts] sensor_model` and `simp-demo
/// --method` (the object models), `simp-eval batch` (its methods and their table labels) all read it.
/// It lives here because libs/eval (the batch) sits below libs/localization and cannot see it there.

#include <optional>
#include <string>
#include <vector>

namespace simp::model {

/// The 3D-object sensor models; libs/maps implements one value type for each (SensorModel.h).
enum class SensorModelType {
    Simp,  ///< Eqs. globaldist + iouscore + combined (ours)
    Edt,   ///< EDT-MCL: per-class distance transform, beam-end model of the detection centre
    D,     ///< D-MCL: p_o of Eq. globaldist only (centre, no shape)
    O      ///< O-MCL: footprint overlap of Eq. iouscore only (no noise model)
};

/// One localization method: which sensors weigh the particles.
struct LocalizationMethod {
    const char* name;   ///< as `--method` takes it; for an object model alone also its `sensor_model` name
    const char* label;  ///< row label in the batch tables (the paper's names)
    std::optional<SensorModelType> object_model;  ///< weighs the object detections; none: detections unused
    bool uses_scans;    ///< weighs 2D laser scans against the floor plan (localization's ScanLikelihood)

    /// One object model and nothing else: the method that names that model.
    bool isObjectModelAlone() const { return object_model.has_value() && !uses_scans; }
};

/// Every method, in the order of the batch tables' rows.
const std::vector<LocalizationMethod>& localizationMethods();
/// Their names, in that order.
const std::vector<std::string>& localizationMethodNames();
/// The method called `name` (exact, as `--method`), or nullptr.
const LocalizationMethod* findLocalizationMethod(const std::string& name);

/// The object models' names in the table's order ("simp", "edt", "d", "o"): the names of the methods
/// that run one object model alone, i.e. the paper's comparison, which needs no scans.
const std::vector<std::string>& sensorModelTypeNames();
/// A name of sensorModelTypeNames() (case-insensitive); \throw std::invalid_argument listing them.
SensorModelType parseSensorModelType(const std::string& name);
/// Lower-case name, as parsed.
std::string toString(SensorModelType type);

}  // namespace simp::model
