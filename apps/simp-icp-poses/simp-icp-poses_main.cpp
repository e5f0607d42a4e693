/// simp-icp-poses: scan-matched poses from odometry + 2D LiDAR (doc/lidar.md).
#include <simp/lidar/IcpPosesApp.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::lidar::IcpPosesApp app;
        if (!app.initialize(std::vector<std::string>(argv + 1, argv + argc), std::cout)) return 0;
        app.run(std::cout);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-icp-poses: error: " << e.what() << "\n";
        return 1;
    }
}
