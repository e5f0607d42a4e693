// simp-sim: the built-in office world and simulated sequences (logic in simp::sim::SimApp).
#include <simp/sim/SimApp.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::sim::SimApp app;
        if (!app.initialize(std::vector<std::string>(argv + 1, argv + argc), std::cout)) return 0;
        app.run(std::cout);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-sim: error: " << e.what() << "\n";
        return 1;
    }
}
