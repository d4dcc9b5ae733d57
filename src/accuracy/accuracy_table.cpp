// accuracy-table: the work–precision sweep of docs/accuracy.md. Runs the standard scenes in
// every mode over a range of step sizes and writes accuracy.csv and accuracy-table.md to the output
// directory; scripts/accuracy_plot.py draws the SVG from the CSV.
//
//   accuracy-table [--quick] [--out DIR] [--root DIR] [--scene NAME]...
//
// --root is the source tree holding assets/scenes and bench/scenes (default: the one this was
// built from). --scene restricts the sweep to the named scenes. Exit status 0 ok, 1 a scene or
// output file failed, 2 bad command line.

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>

#include "accuracy_sweep.hpp"

#ifndef PSB_SOURCE_DIR
#define PSB_SOURCE_DIR "."
#endif

namespace {

int usage(const std::string& message) {
    std::cerr << "accuracy-table: error: " << message
              << "\nusage: accuracy-table [--quick] [--out DIR] [--root DIR] [--scene NAME]...\n";
    return 2;
}

bool writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        std::cerr << "accuracy-table: error: cannot write " << path.string() << "\n";
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace psb::cli;
    bool quick = false;
    std::filesystem::path out = ".";
    std::filesystem::path root = PSB_SOURCE_DIR;
    std::vector<std::string> only;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](std::string& v) {
            if (i + 1 >= argc) return false;
            v = argv[++i];
            return true;
        };
        std::string v;
        if (a == "--quick") {
            quick = true;
        } else if (a == "--out" || a == "--root" || a == "--scene") {
            if (!value(v)) return usage(a + " needs a value");
            if (a == "--out") out = v;
            if (a == "--root") root = v;
            if (a == "--scene") only.push_back(v);
        } else if (a == "--help" || a == "-h") {
            std::cout << "usage: accuracy-table [--quick] [--out DIR] [--root DIR] "
                         "[--scene NAME]...\n";
            return 0;
        } else {
            return usage("unknown argument '" + a + "'");
        }
    }

    std::vector<AccuracyScene> scenes;
    for (const AccuracyScene& s : standardScenes(root)) {
        if (only.empty() || std::find(only.begin(), only.end(), s.name) != only.end())
            scenes.push_back(s);
    }
    for (const std::string& name : only) {
        const bool known = std::any_of(scenes.begin(), scenes.end(),
                                       [&](const AccuracyScene& s) { return s.name == name; });
        if (!known) return usage("--scene: unknown scene '" + name + "'");
    }

    try {
        const auto rows =
            runSweep(scenes, quick ? quickPlan() : fullPlan(), [](const AccuracyRow& r) {
                std::fprintf(stderr, "%-18s %-8s dt %.5g s k %-2d  %.3g wall s/sim s\n",
                             r.scene.c_str(), std::string(psb::toString(r.mode)).c_str(), r.dt,
                             r.substeps, r.errors.wallSecondsPerSimSecond);
            });
        if (!writeFile(out / "accuracy.csv", accuracyCsv(rows))) return 1;
        if (!writeFile(out / "accuracy-table.md", accuracyMarkdown(rows))) return 1;
    } catch (const std::exception& e) {
        std::cerr << "accuracy-table: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
