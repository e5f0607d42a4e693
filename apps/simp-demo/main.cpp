// simp-demo: the whole pipeline on the built-in office world (doc/demo.md).
#include <simp/demo/DemoApp.h>

#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::demo::DemoApp app;
        if (!app.initialize(std::vector<std::string>(argv + 1, argv + argc), std::cout)) return 0;
        app.run(std::cout);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-demo: error: " << e.what() << "\n";
        return 1;
    }
}
