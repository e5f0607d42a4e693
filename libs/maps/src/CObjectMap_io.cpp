#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/ArchiveRead.h>
#include <simp/obs/InputLimits.h>
#include <simp/world/ObjectMapData.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

IMPLEMENTS_SERIALIZABLE(CObjectMap, CMetricMap, simp::maps)

namespace simp::maps {
namespace {

// Version history (doc/object-map.md):
//  0: generic map params, likelihood options, class names + class noise, objects
constexpr std::uint8_t kVersion = 0;
const std::string kWhere = "CObjectMap archive";

void writeNoise(mrpt::serialization::CArchive& out, const std::optional<simp::model::NoiseModel>& n) {
    out << n.has_value();
    if (!n) return;
    out << n->mean_m.x() << n->mean_m.y() << n->cov_m2(0, 0) << n->cov_m2(0, 1) << n->cov_m2(1, 0) << n->cov_m2(1, 1)
        << n->exponent_b;
}

std::optional<simp::model::NoiseModel> readNoise(mrpt::serialization::CArchive& in, const std::string& what) {
    if (!simp::obs::archive::readBool(in, what + ": field 'has_noise'")) return std::nullopt;
    simp::model::NoiseModel n;
    in >> n.mean_m.x() >> n.mean_m.y() >> n.cov_m2(0, 0) >> n.cov_m2(0, 1) >> n.cov_m2(1, 0) >> n.cov_m2(1, 1) >>
        n.exponent_b;
    return n;
}

}  // namespace

uint8_t CObjectMap::serializeGetVersion() const { return kVersion; }

void CObjectMap::serializeTo(mrpt::serialization::CArchive& out) const {
    out << genericMapParams;
    // Likelihood options.
    const auto& o = likelihoodOptions;
    out << toString(o.sensor_model) << o.eta << formatConfidenceThresholds(o.confidence_thresholds)
        << o.default_confidence_threshold << o.mp_resolution_m << o.mp_min_probability << o.skip_classes_without_noise
        << o.edt_sigma_m << o.edt_max_distance_m << o.edt_resolution_m;
    // Content.
    out << m_data.class_names;
    out.WriteAs<uint32_t>(m_data.class_noise.size());
    for (const auto& n : m_data.class_noise) writeNoise(out, n);
    out.WriteAs<uint32_t>(m_data.objects.size());
    for (const auto& obj : m_data.objects) {
        const Eigen::Quaterniond q(obj.box.R);
        out << obj.id << static_cast<int32_t>(obj.class_id);
        out << obj.box.center.x() << obj.box.center.y() << obj.box.center.z();
        out << obj.box.size.x() << obj.box.size.y() << obj.box.size.z();
        out << q.w() << q.x() << q.y() << q.z();
        out << static_cast<int32_t>(obj.n_match) << static_cast<int32_t>(obj.n_skip) << static_cast<int32_t>(obj.room_id);
        writeNoise(out, obj.noise);
    }
}

void CObjectMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    switch (version) {
        case 0: {
            in >> genericMapParams;
            TLikelihoodOptions o;
            std::string model, thresholds;
            // Untrusted bytes: lengths and counts are checked before allocating (ArchiveRead.h),
            // bools must be 0/1; the content is validated by validateObjectMap (limits of
            // doc/formats.md) before it replaces the current one.
            namespace ar = simp::obs::archive;
            namespace lim = simp::obs::limits;
            model = ar::readString(in, lim::kMaxNameLength, kWhere + ": field 'sensor_model'");
            in >> o.eta;
            thresholds = ar::readString(in, 64 * lim::kMaxNameLength, kWhere + ": field 'confidence_thresholds'");
            in >> o.default_confidence_threshold >> o.mp_resolution_m >> o.mp_min_probability;
            o.skip_classes_without_noise = ar::readBool(in, kWhere + ": field 'skip_classes_without_noise'");
            in >> o.edt_sigma_m >> o.edt_max_distance_m >> o.edt_resolution_m;
            o.sensor_model = model::parseSensorModelType(model);
            o.confidence_thresholds = parseConfidenceThresholds(thresholds, "CObjectMap archive: confidence_thresholds");

            simp::world::ObjectMapData data;
            data.class_names =
                ar::readStringList(in, lim::kMaxClasses, lim::kMaxNameLength, kWhere + ": field 'class_names'");
            // A noise entry takes >= 1 byte (its flag), an object >= 105 (id, class, 10 doubles,
            // 3 counters, noise flag).
            const auto num_noise = ar::readCount(in, 1, lim::kMaxClasses, kWhere + ": class noise count");
            data.class_noise.resize(num_noise);
            for (std::size_t c = 0; c < num_noise; ++c)
                data.class_noise[c] = readNoise(in, kWhere + ": class_noise[" + std::to_string(c) + "]");
            const auto num_objects = ar::readCount(in, 105, lim::kMaxMapObjects, kWhere + ": object count");
            data.objects.resize(num_objects);
            for (std::size_t i = 0; i < num_objects; ++i) {
                const std::string where = kWhere + ": object #" + std::to_string(i);
                auto& obj = data.objects[i];
                int32_t class_id, n_match, n_skip, room_id;
                double cx, cy, cz, w, h, l, qw, qx, qy, qz;
                in >> obj.id >> class_id >> cx >> cy >> cz >> w >> h >> l >> qw >> qx >> qy >> qz >> n_match >> n_skip >>
                    room_id;
                obj.noise = readNoise(in, where);
                const Eigen::Quaterniond q(qw, qx, qy, qz);
                if (!std::isfinite(q.norm()) || std::abs(q.norm() - 1.0) > 1e-3)
                    throw std::invalid_argument(where + ": rotation is not a unit quaternion");
                obj.class_id = class_id;
                obj.box.center = {cx, cy, cz};
                obj.box.size = {w, h, l};
                obj.box.R = q.normalized().toRotationMatrix();
                obj.n_match = n_match;
                obj.n_skip = n_skip;
                obj.room_id = room_id;
            }
            for (double v : {o.eta, o.default_confidence_threshold, o.mp_resolution_m, o.mp_min_probability,
                             o.edt_sigma_m, o.edt_max_distance_m, o.edt_resolution_m})
                if (!std::isfinite(v)) throw std::invalid_argument(kWhere + ": a likelihood option is not finite");
            simp::world::validateObjectMap(data, kWhere);
            likelihoodOptions = o;
            setData(data);
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

void CObjectMap::saveMetricMapRepresentationToFile(const std::string& filNamePrefix) const {
    simp::world::saveObjectMap(m_data, filNamePrefix + "_objects.json");
    const std::string summary_path = filNamePrefix + "_summary.txt";
    std::ofstream f(summary_path);
    if (!f) throw std::runtime_error("CObjectMap: cannot write '" + summary_path + "'");
    f << asString() << "\n\n";
    f << "objects per class:\n";
    std::vector<std::size_t> counts(m_data.class_names.size(), 0);
    for (const auto& obj : m_data.objects)
        if (obj.class_id >= 0 && static_cast<std::size_t>(obj.class_id) < counts.size()) ++counts[obj.class_id];
    for (std::size_t c = 0; c < counts.size(); ++c)
        f << "  " << std::setw(20) << std::left << m_data.class_names[c] << " " << counts[c]
          << (c < m_data.class_noise.size() && m_data.class_noise[c] ? "" : "  (no class noise model)") << "\n";
    f << "\nobjects (id class centre_x centre_y centre_z [m] size_x size_y size_z [m] yaw [rad]):\n";
    f << std::fixed << std::setprecision(3);
    for (const auto& obj : m_data.objects)
        f << obj.id << " " << m_data.class_names.at(static_cast<std::size_t>(obj.class_id)) << " " << obj.box.center.x()
          << " " << obj.box.center.y() << " " << obj.box.center.z() << " " << obj.box.size.x() << " "
          << obj.box.size.y() << " " << obj.box.size.z() << " " << geometry::yawOf(obj.box) << "\n";
    f << "\n";
    likelihoodOptions.dumpToTextStream(f);
    if (!f) throw std::runtime_error("CObjectMap: error writing '" + summary_path + "'");
}

}  // namespace simp::maps
