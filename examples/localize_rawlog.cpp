// Global localization of a rawlog on a SIMP world with the library API: what simp-localize does,
// reduced to its core loop. Prints the final pose, the filter's state and, given the ground truth,
// the final error.
//
//   localize_rawlog W Q/sequence.rawlog [Q/groundtruth.tum] [particles]
//
// W is a world directory (floorplan.yaml + objects.json, e.g. from `simp-sim world`), the rawlog
// one written by `simp-sim sequence` (or any rawlog of simp::obs::CObservationObjects3D).

#include <mrpt/random/RandomGenerators.h>
#include <simp/io/Tum.h>
#include <simp/localization/LocalizeApp.h>  // defaultLikelihoodOptions()
#include <simp/localization/Localizer.h>
#include <simp/localization/RawlogSequence.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/registerAllClasses.h>
#include <simp/world/World.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace loc = simp::localization;

int main(int argc, char** argv) {
    if (argc < 3 || argc > 5) {
        std::cerr << "usage: localize_rawlog WORLD_DIR SEQUENCE.rawlog [GROUNDTRUTH.tum] [PARTICLES]\n";
        return 2;
    }
    try {
        // Make MRPT's deserializer know the detection observation before the rawlog is read
        // (loading libsimp_obs.so registers it too; this also works with --as-needed linking).
        simp::obs::registerAllClasses();

        // The world: floor plan (free space for the particles) and the 3D object map.
        const simp::world::World world = simp::world::loadWorld(argv[1]);
        auto map = std::make_shared<simp::maps::CObjectMap>();
        map->likelihoodOptions = loc::defaultLikelihoodOptions();  // the sensor model of config_ini/simp.ini
        map->setData(world.objects);

        // Filter options: the defaults are config_ini/simp.ini's values; change fields as needed.
        loc::LocalizerOptions options;
        if (argc == 5) options.experiment.particles_count = std::stoul(argv[4]);
        mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(options.experiment.seed);

        // world and map must outlive the localizer (it keeps references).
        loc::Localizer localizer(map, world.floorplan, options);
        localizer.startGlobal();  // particles uniform over the free space: global localization

        // One odometry increment and one sensory frame (all cameras at one time) per step.
        const loc::RawlogSequence seq = loc::loadRawlogSequence(argv[2]);
        loc::StepRecord last;
        std::size_t localized_steps = 0;
        for (const loc::SequenceFrame& frame : seq.frames) {
            last = localizer.step(frame.t_s, frame.odometry_increment, *frame.observations);
            if (last.state == loc::LocalizationState::Localized) ++localized_steps;
        }

        std::printf("frames: %zu, particles at the end: %zu\n", seq.frames.size(), last.particles);
        std::printf("final pose: x = %.3f m, y = %.3f m, phi = %.3f rad (t = %.2f s)\n", last.estimate.x,
                    last.estimate.y, last.estimate.phi, last.t_s);
        std::printf("final state: %s (cluster weight %.2f; localized in %zu of %zu frames)\n",
                    loc::toString(last.state).c_str(), last.cluster_weight, localized_steps, seq.frames.size());

        if (argc >= 4) {
            // The ground truth at the last frame's time: the final error.
            const auto gt = simp::io::readTum(argv[3]);
            mrpt::math::TPose2D truth;
            if (!simp::io::interpolatePose(gt, last.t_s, truth))
                throw std::runtime_error(std::string(argv[3]) + " does not cover t = " + std::to_string(last.t_s));
            const double dphi = std::remainder(last.estimate.phi - truth.phi, 2 * M_PI);
            std::printf("final error: %.3f m, %.3f rad\n", std::hypot(last.estimate.x - truth.x, last.estimate.y - truth.y),
                        std::abs(dphi));
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "localize_rawlog: " << e.what() << "\n";
        return 1;
    }
}
