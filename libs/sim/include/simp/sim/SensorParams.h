#pragma once
/// \file SensorParams.h
/// Knobs of the simulated camera rig, of visibility and of the detector (sections [cameras],
/// [visibility], [detector], [false_positives], [people], [lidar] of sim.ini). Each struct's keys are
/// declared once in its table() (SensorParams.cpp): loading, range checks, dump and the key tables of
/// doc/simulator.md derive from it.

#include <mrpt/config/CConfigFileBase.h>
#include <simp/camera/PinholeCamera.h>
#include <simp/io/OptionTable.h>

#include <string>
#include <vector>

namespace simp::sim {

/// [cameras]: N cameras on a ring around the robot centre, optical axes horizontal.
struct CameraParams {
    int count = 4;                  ///< number of cameras, in [1, 16]
    double first_yaw_deg = 0;       ///< yaw of camera 0 (deg, 0 = robot forward, 90 = left); camera i at +i*360/count
    double mount_radius_m = 0.1;    ///< distance of each camera from the robot centre along its yaw (m)
    double height_m = 0.63;         ///< camera height above the floor (m)
    double pitch_down_deg = 0;      ///< downward tilt (deg)
    /// Keys width_px, height_px, fx, fy, cx, cy (px); default camera::defaultIntrinsics().
    mrpt::img::TCamera intrinsics = camera::defaultIntrinsics();
    double rate_hz = 5;             ///< frame rate (Hz); a divisor of the odometry rate is best

    static const io::OptionTable<CameraParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// [visibility]: which objects a camera can see.
struct VisibilityParams {
    /// Per class (simp::obs::defaultClassNames() order) minimum / maximum detection range (m,
    /// horizontal distance camera -> box centre); 0 = no limit (maximum: default_max_range_m).
    std::vector<double> min_range_m{0.5, 0.0, 0.0, 1.5, 1.0, 0.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 0.5};
    std::vector<double> max_range_m{3.0, 0.0, 4.0, 4.5, 4.5, 0.0, 4.5, 3.5, 3.0, 5.0, 0.0, 3.0, 0.0, 4.0};
    double default_max_range_m = 5.0;     ///< range limit of classes with max 0 (m)
    double min_inside_fraction = 0.5;     ///< truncation: fraction of the 8 projected corners inside the image
    int render_downscale = 4;             ///< image pixels per rendered pixel (per side) of the occlusion renderer
    double wall_depth_margin_m = 0.1;     ///< box surfaces up to this far behind the first wall face still count in front of it (m)
    double self_margin_m = 0.05;          ///< wall cells this close to an object's footprint are the object drawn into the plan (m)
    double min_unwalled_fraction = 0.4;   ///< wall occlusion: fraction of the box's rendered pixels that must lie in front of the walls
    double max_occluded_fraction = 0.7;   ///< object occlusion: of those, the fraction nearer boxes may hide

    /// The per-class lists hold one value per class of simp::obs::defaultClassNames().
    static const io::OptionTable<VisibilityParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// [detector]: what a visible object becomes.
struct DetectorParams {
    double detection_probability = 0.85;   ///< probability that a visible object is detected
    double default_noise_std_m = 0.15;     ///< centre std (m) for classes without a noise model
    double z_std_m = 0.05;                 ///< std of the box centre height (m)
    double size_std_fraction = 0.1;        ///< relative std of each box dimension
    double yaw_std_rad = 0.1;              ///< std of the box yaw (rad)
    double wrong_class_probability = 0.03; ///< a true detection gets another class label
    double confidence_true_mean = 0.93, confidence_true_std = 0.05;   ///< score of true detections
    double confidence_false_mean = 0.55, confidence_false_std = 0.12; ///< score of false ones
    double min_confidence = 0.3;           ///< detections scoring below are not reported
    /// Centre noise structure (doc/simulator.md "Detection noise"): the class model holds at this
    /// camera -> object distance (m); the error component along the viewing ray scales with
    /// distance / reference_distance_m.
    double reference_distance_m = 3.0;
    /// Fraction of the centre-noise variance that is persistent per object and viewpoint (the same
    /// object seen from a similar pose gives a similar error); the rest is per-frame jitter.
    /// Calibrated on the paper's map of the authors' office (config_ini/sim.ini, doc/results.md).
    double persistent_variance_fraction = 0.1;
    /// Viewpoint cells of the persistent component: bearing object -> camera (deg) and distance (m).
    double viewpoint_bin_deg = 45.0;
    double viewpoint_bin_m = 1.5;
    /// The class / object noise models are the authors' fits to heatmaps of rasterized detected
    /// FOOTPRINTS (doc/simulator.md "Detection noise"), so their spread includes the object's own
    /// extent: true = the centre noise is the model's covariance minus the footprint's (uniform
    /// box: side^2 / 12 per axis of the noise frame); false = the model is the centre noise.
    bool noise_model_includes_extent = true;
    /// Lower bound of the centre-noise std per axis, as a fraction of the model's std (where the
    /// extent explains nearly all of the model's spread).
    double min_centre_noise_fraction = 0.25;

    static const io::OptionTable<DetectorParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// [false_positives]: phantom boxes where nothing is.
struct FalsePositiveParams {
    double rate_per_frame = 0.05;  ///< expected phantoms per camera frame (Poisson)
    double range_min_m = 1.0, range_max_m = 5.0;  ///< phantom distance from the camera (m)

    static const io::OptionTable<FalsePositiveParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// [people]: people walking through the floor (class "person", never in the map).
struct PeopleParams {
    int count = 2;                                     ///< people on the floor, in [0, 100]
    double speed_min_mps = 0.6, speed_max_mps = 1.2;  ///< walking speed, uniform in [min, max] (m/s)

    static const io::OptionTable<PeopleParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/// [lidar]: a planar 2D laser scanner (defaults: a Hokuyo UTM-30LX) writing
/// mrpt::obs::CObservation2DRangeScan observations (doc/lidar.md).
struct LidarParams {
    bool enabled = false;         ///< write scans (simp-sim sequence --lidar sets it)
    /// Scans per second (Hz). The rawlog holds one sensory frame per odometry step, so at most one scan
    /// per step is written: the effective rate is min(rate_hz, [odometry] rate_hz).
    double rate_hz = 40;
    double fov_deg = 270;         ///< aperture, centred on the sensor's x axis (deg)
    int beams = 1081;             ///< rays over the aperture (first and last at +-fov/2)
    double max_range_m = 30;      ///< beyond it a ray is not valid (m)
    double range_std_m = 0.02;    ///< Gaussian range noise (m)
    double x_m = 0.0, y_m = 0.0;  ///< sensor position on the robot (m, robot frame)
    double height_m = 0.3;        ///< scan plane above the floor (m): objects spanning it are seen
    double yaw_deg = 0.0;         ///< sensor heading on the robot (deg)

    static const io::OptionTable<LidarParams>& table();
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

}  // namespace simp::sim
