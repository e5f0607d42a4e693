#pragma once
/// \file CObjectMap.h
/// The 3D object map as an MRPT metric map, with the paper's 3D-object sensor model.

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/math/TPose2D.h>
#include <simp/io/OptionTable.h>
#include <simp/maps/ConfidenceThresholds.h>
#include <simp/maps/ObjectMapInserter.h>
#include <simp/maps/SensorModel.h>
#include <simp/maps/SensorModelTypes.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/world/ObjectMapData.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simp::maps {

/** A map of 3D objects (class, oriented box, noise model) in the world frame (doc/object-map.md).
 *
 * Likelihood of a simp::obs::CObservationObjects3D (paper Sec. "3D Semantic Localization"):
 * per detection Eq. combined (or a baseline, TLikelihoodOptions::sensor_model), per
 * observation the geometric mean of Eq. singw, returned as a log. Other observation types
 * are not handled (log-likelihood 0, canComputeObservationLikelihood() false).
 *
 * Detections are ignored (no factor in Eq. singw) when their confidence is below their class
 * threshold, or when the map has no object of their class (by class name).
 *
 * In an .ini [MetricMap] section: `semanticObjectMap_count=1`, options in
 * `<prefix>_semanticObjectMap_00_{creationOpts,likelihoodOpts,insertOpts}`.
 */
class CObjectMap : public mrpt::maps::CMetricMap {
    DEFINE_SERIALIZABLE(CObjectMap, simp::maps)

   public:
    CObjectMap();
    CObjectMap(const CObjectMap& other);
    CObjectMap& operator=(const CObjectMap& other);

    /// @name Content
    /// @{
    /// Replaces the map content. With sensor_model simp or d, validates the noise models now:
    /// throws std::invalid_argument naming the class that has none (see skip_classes_without_noise).
    void setData(const simp::world::ObjectMapData& data);
    const simp::world::ObjectMapData& data() const { return m_data; }
    /// Number of objects.
    std::size_t size() const { return m_data.objects.size(); }
    /// @}

    /** Options of the sensor model ([<prefix>_likelihoodOpts]). A public member, as in MRPT's
     * maps: changes are picked up at the next likelihood evaluation (the precomputed rasters
     * are rebuilt when a parameter they depend on changed). */
    struct TLikelihoodOptions : public mrpt::config::CLoadableOptions {
        /// The declaration of every key (CObjectMap_options.cpp): loading, checks and the dump.
        static const io::OptionTable<TLikelihoodOptions>& table();
        void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
        void dumpToTextStream(std::ostream& out) const override;

        SensorModelType sensor_model = SensorModelType::Simp;  ///< key sensor_model = simp | edt | d | o
        /// Eq. combined: likelihood of a false association, in (0, 1). 0.1: below exp(-1), the
        /// smallest p_g, so p grows with p_o; one detection changes a weight by at most x10.
        double eta = 0.1;
        /// Per-class thresholds, key `confidence_thresholds` = "name:value, ..." (overrides the
        /// paper's defaults class by class).
        ConfidenceThresholds confidence_thresholds = paperConfidenceThresholds();
        /// Threshold for classes missing from confidence_thresholds.
        double default_confidence_threshold = 0.5;
        double mp_resolution_m = 0.05;     ///< m_p raster cell (m)
        double mp_min_probability = 1e-4;  ///< m_p support: p_o below this counts as 0
        bool skip_classes_without_noise = false;  ///< true: ignore such classes instead of throwing
        /// > 0: an object without noise model (its own or its class's) gets an isotropic Gaussian
        /// of this std (m) instead of being skipped; 0 = none (the paper). Not serialized (like
        /// noise_reference_range_m): it comes from the .ini.
        double unmodelled_noise_std_m = 0.0;
        /// > 0: each object's noise model without its own footprint (model::withoutFootprint: the
        /// authors' models are fitted to heatmaps of detected footprints, not to centres), floored
        /// at this fraction of its std; 0 = the model as is (the paper). Not serialized (like
        /// noise_reference_range_m): it comes from the .ini.
        double mp_centre_noise_floor = 0.35;
        double edt_sigma_m = 0.3;          ///< EDT baseline: std. dev. of the centre distance (m)
        double edt_max_distance_m = 2.0;   ///< EDT baseline: distance clamp (m)
        double edt_resolution_m = 0.05;    ///< EDT baseline: raster cell (m)
        /// Range growth of the detection noise (m): detections farther than this from the robot are
        /// scored with the noise model widened by range / this. 0 = off (the paper's model).
        double noise_reference_range_m = 3.0;
        /// > 0: std (rad) of a detected box's yaw about its map object's (SimpSensorModelParams::
        /// yaw_sigma_rad; simp model only): the detections' headings hold the robot's heading where
        /// their centres are few. 0 = off (the paper). Not serialized (like noise_reference_range_m):
        /// it comes from the .ini.
        double yaw_sigma_rad = 0.1;

        /// Threshold for a class name.
        double thresholdOf(const std::string& class_name) const;
        /// The parameters of the precomputed model.
        SensorModelParams modelParams() const;
    } likelihoodOptions;

    /// [<prefix>_insertOpts]: the options of the map construction insertObservation() runs
    /// (ObjectMapInserter.h): with libsimp_mapping.so loaded, simp::mapping::MappingOptions (keys in
    /// doc/mapping.md). A value: copies of the options do not share state.
    struct TInsertionOptions : public mrpt::config::CLoadableOptions {
        /// The registered algorithm's defaults (none when no algorithm is registered yet).
        TInsertionOptions();
        TInsertionOptions(const TInsertionOptions& other);
        TInsertionOptions& operator=(const TInsertionOptions& other);
        /// With an algorithm registered, its options read the section: its keys are the known ones
        /// (io::StrictIni rejects the others) and a bad value throws. Without one, the section's
        /// keys are kept as text and read by the algorithm when insertion starts.
        void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
        void dumpToTextStream(std::ostream& out) const override;
        /// The options `factory`'s runs take: `algorithm`, made first when absent, with the kept
        /// keys read into it (an unknown key throws, as io::StrictIni does).
        const ObjectMapInserterOptions& resolve(const ObjectMapInserterFactory& factory);

        /// The registered algorithm's options; nullptr when none was registered when these were
        /// made or loaded.
        std::unique_ptr<ObjectMapInserterOptions> algorithm;
        /// Without an algorithm: the section that was loaded and its keys (name, value) as text.
        std::string kept_section;
        std::vector<std::pair<std::string, std::string>> kept_keys;
    } insertionOptions;

    /// @name Map construction (paper Sec. "3D Semantic Map Construction": libs/mapping registers it)
    /// @{
    /// Integrates the pending local map into the map now (insertObservation() integrates only
    /// when the robot moved d_xy or turned d_theta, as the paper does).
    void flushInsertions();
    /// The run used by insertObservation(), or nullptr before the first insertion.
    const ObjectMapInserter* inserter() const { return m_inserter.get(); }
    /// @}

    /// @name Sensor model
    /// @{
    /// log p(z_k | m, x) for detection k (Eq. combined or the baseline's), robot at pose
    /// (x, y, phi) (world, m, rad); std::nullopt when the detection is ignored (under its class
    /// threshold, class not in the map).
    std::optional<double> detectionLogLikelihood(const simp::obs::CObservationObjects3D& obs, std::size_t k,
                                                 const mrpt::math::TPose2D& robot_pose) const;

    /// Fast batch path for N particle poses: adds log p of every used detection to sum_log[i]
    /// and the number of used detections to `used` (same for all particles). With `weights`
    /// (one per detection of `obs`), detection k adds weights[k] log p instead; weight 0 = not
    /// used (not counted either).
    void accumulateLogLikelihoods(const simp::obs::CObservationObjects3D& obs, const mrpt::math::TPose2D* poses,
                                  std::size_t n, double* sum_log, std::size_t& used,
                                  const double* weights = nullptr) const;
    /// One observation of several weighed together, with the exponents of its detections
    /// (nullptr = all 1).
    struct WeightedDetections {
        const simp::obs::CObservationObjects3D* obs = nullptr;
        const double* weights = nullptr;  ///< one per detection of obs, or nullptr
    };
    /// accumulateLogLikelihoods() of each of `num_observations` observations in order (e.g. the
    /// cameras of one frame): the same sums, bit for bit, with the cos/sin of each pose computed
    /// once for all of them.
    void accumulateLogLikelihoods(const WeightedDetections* observations, std::size_t num_observations,
                                  const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log,
                                  std::size_t& used) const;
    /// Map class id of detection k of `obs`, or -1 when it is ignored (under its class threshold,
    /// class not in the map, or a class the sensor model cannot score).
    int usableClassOf(const simp::obs::CObservationObjects3D& obs, std::size_t k) const;

    /// The precomputed model for the current data and likelihoodOptions (built on demand).
    std::shared_ptr<const SensorModel> sensorModel() const;
    /// @}

    /// @name mrpt::maps::CMetricMap
    /// @{
    bool isEmpty() const override { return m_data.objects.empty(); }
    /// Writes <prefix>_objects.json (the object map file) and <prefix>_summary.txt.
    void saveMetricMapRepresentationToFile(const std::string& filNamePrefix) const override;
    /// One wireframe mrpt::opengl::CBox per object, coloured by class, with a class label.
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const override;
    std::string asString() const override;
    /// @}

    /// RGB colour (0..255) of a class id of the default class list (obs::defaultClassNames()):
    /// obs::classColorRgb(class_id). The pictures colour a class by its name, so for a map with its
    /// own class list use obs::classColorRgb(class_id, data().class_names) instead.
    static std::array<std::uint8_t, 3> classColor(int class_id);

    MAP_DEFINITION_START(CObjectMap)
    std::string map_file;     ///< [_creationOpts] map_file: object map (JSON) to load; empty = empty map
    std::string class_names;  ///< [_creationOpts] class_names: optional comma-separated class list
    simp::maps::CObjectMap::TLikelihoodOptions likelihoodOpts;
    simp::maps::CObjectMap::TInsertionOptions insertionOpts;
    /// Why loading the options failed (empty = they loaded). MRPT 2.5's
    /// TSetOfMetricMapInitializers holds a new definition by a raw pointer while it loads it and
    /// leaks it when loading throws, so the error is kept here and thrown when the map is created.
    std::string load_error;
    MAP_DEFINITION_END(CObjectMap)

   private:
    void internal_clear() override;
    bool internal_insertObservation(const mrpt::obs::CObservation& obs,
                                    const std::optional<const mrpt::poses::CPose3D>& robotPose) override;
    double internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
                                                 const mrpt::poses::CPose3D& takenFrom) const override;
    bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const override;

    /// Detections of `obs` that take part, prepared in the robot frame; returns how many were
    /// written to `out` (capacity `cap`), starting at detection `first` (advanced past the last read).
    std::size_t prepareDetections(const SensorModel& model, const simp::obs::CObservationObjects3D& obs,
                                  std::size_t& first, PreparedDetection* out, std::size_t cap,
                                  const double* weights) const;
    void warnEmptyOnce() const;
    /// Copies the inserter's map into m_data when it changed; the model is rebuilt lazily.
    void syncFromInserter();

    simp::world::ObjectMapData m_data;
    mutable std::mutex m_cache_mutex;
    mutable std::shared_ptr<const SensorModel> m_model;  ///< built for m_data and m_model->params()
    mutable bool m_warned_empty = false;
    /// Map construction state (local map, counters); reset by setData() and not copied with the map.
    std::unique_ptr<ObjectMapInserter> m_inserter;
};

/// Applies a class list to a map: objects of other classes are dropped, class ids and class
/// noise follow the names. Used by the `class_names` creation option.
simp::world::ObjectMapData restrictToClasses(const simp::world::ObjectMapData& data,
                                             const std::vector<std::string>& class_names);

}  // namespace simp::maps
