/// config_ini/batch.ini names the directories the main demo writes: a small simp-demo run (the same
/// layout as `simp-demo --out demo_out`, the README's demo command) into a temporary root, then every
/// path of batch.ini, with its `demo_out/` prefix put under that root, is loaded as the batch loads it.

#include <gtest/gtest.h>
#include <simp/demo/DemoApp.h>
#include <simp/eval/BatchConfig.h>
#include <simp/io/Tum.h>
#include <simp/world/World.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace {

/// `path` (relative to the project root) with the demo's output folder "demo_out" replaced by `root`.
fs::path underDemoRoot(const std::string& path, const fs::path& root) {
    const std::string prefix = "demo_out/";
    EXPECT_EQ(path.rfind(prefix, 0), 0u) << path << " is not in the demo's output folder";
    return root / path.substr(prefix.size());
}

}  // namespace

TEST(DemoBatch, BatchIniNamesTheDirectoriesTheDemoWrites) {
    // The README's demo command runs `.ci/setup.sh demo` = `simp-demo --out demo_out` from the project root.
    const fs::path root = fs::path(SIMP_TEST_OUTPUT_DIR) / "demo_batch" / "demo_out";
    fs::remove_all(root);
    simp::demo::DemoApp demo;
    std::ostringstream log;
    // Small and fast, same layout: default number of runs (R1..R3), short sequences, few particles.
    ASSERT_TRUE(demo.initialize({"--out", root.string(), "--rooms", "3", "--mapping-duration", "30", "--duration", "8",
                                 "--particles", "200"},
                                log));
    demo.run(log);
    ASSERT_EQ(demo.runs.size(), 3u) << "the demo's default run count changed: update batch.ini's sequences";

    const auto cfg = simp::eval::loadBatchConfig(std::string(SIMP_SOURCE_DIR) + "/config_ini/batch.ini");
    // The map: a world directory the batch's simp-localize runs load.
    const auto world = simp::world::loadWorld(underDemoRoot(cfg.world, root).string());
    EXPECT_GT(world.objects.objects.size(), 10u);
    ASSERT_EQ(cfg.sequences.size(), demo.runs.size());
    for (std::size_t k = 0; k < cfg.sequences.size(); ++k) {
        EXPECT_EQ(cfg.sequences[k].name, demo.runs[k].name);
        const fs::path q = underDemoRoot(cfg.sequences[k].dir, root);
        EXPECT_TRUE(fs::is_regular_file(q / "sequence.rawlog")) << q;
        // 8 s of ground truth at the simulator's 10 Hz.
        EXPECT_GE(simp::io::readTum((q / "groundtruth.tum").string()).size(), 70u) << q;
    }
    // The localization config is the project's, relative to the project root.
    EXPECT_TRUE(fs::is_regular_file(fs::path(SIMP_SOURCE_DIR) / cfg.localize_config)) << cfg.localize_config;
}
