/// simp-eval: the paper's localization and map metrics, batch experiments and plots.
/// The logic lives in simp::eval::EvalApp (libs/eval); usage: simp-eval --help.
#include <simp/eval/EvalApp.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::eval::EvalApp app;
        app.initialize(argc, argv);
        return app.run(std::cout, std::cerr);
    } catch (const std::exception& e) {
        std::cerr << "simp-eval: error: " << e.what() << "\n";
        return 1;
    }
}
