// raylab-exercise: the code track's teacher side. `list` prints the exercises of the manifest;
// `check DIR` grades a folder of pupil files (one pupil's, or one sub-folder per pupil) headlessly
// and writes a table per pupil and exercise: pass/fail, the numbers and what is wrong.
// Usage: raylab-exercise list | raylab-exercise check DIR [--out report.md|report.csv] [--images DIR]
//        [--manifest FILE]
#include "exercise/grading.h"
#include "exercise/manifest.h"
#include "gl/gl_context.h"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>

namespace {

int list(const std::vector<raylab::Exercise>& exercises) {
    std::cout << "name\tslot\tfile\tlevel\tminutes\tchecks\n";
    for (const auto& e : exercises) {
        std::string checks;
        for (const auto& c : e.checks) checks += (checks.empty() ? "" : ",") + c;
        std::cout << e.name << "\t" << e.slot << "\t" << e.file << "\t" << e.level << "\t" << e.minutes << "\t" << checks << "\n";
    }
    return 0;
}

int check(const std::vector<raylab::Exercise>& exercises, const std::string& dir, const std::string& outFile,
          const std::string& imageDir) {
    const bool csv = outFile.size() >= 4 && outFile.substr(outFile.size() - 4) == ".csv";
    if (!outFile.empty() && !csv && !(outFile.size() >= 3 && outFile.substr(outFile.size() - 3) == ".md")) {
        std::cerr << outFile << ": error: --out must end in .md or .csv\n";
        return 1;
    }
    const auto context = raylab::createHeadlessContext();
    const auto pupils = raylab::gradeFolder(dir, exercises, imageDir);
    const std::string table = csv ? raylab::reportCsv(pupils) : raylab::reportMarkdown(pupils);
    if (outFile.empty()) {
        std::cout << table;
        return 0;
    }
    std::ofstream out(outFile);
    if (!(out << table)) {
        std::cerr << outFile << ": error: cannot write the report\n";
        return 1;
    }
    std::cout << "wrote " << outFile << " (" << pupils.size() << " pupil" << (pupils.size() == 1 ? "" : "s") << ")\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"raylab-exercise: the code track's exercises and their grading"};
    app.require_subcommand(1);
    std::string manifest, dir, outFile, imageDir;
    app.add_option("--manifest", manifest, "Exercise manifest (default: the installed exercises/manifest.tsv)");
    app.add_subcommand("list", "Print the exercises: name, slot, file, level, minutes, checks");
    CLI::App* checkCmd = app.add_subcommand("check", "Grade a folder of pupil files headlessly");
    checkCmd->add_option("dir", dir, "One pupil's files, or one sub-folder per pupil")->required();
    checkCmd->add_option("--out", outFile, "Write the table to a .md or .csv file instead of standard output");
    checkCmd->add_option("--images", imageDir, "Write the render check's difference images to DIR/<pupil>/");
    CLI11_PARSE(app, argc, argv);
    try {
        const auto exercises = manifest.empty() ? raylab::loadManifest() : raylab::loadManifest(manifest);
        if (app.got_subcommand("list")) return list(exercises);
        return check(exercises, dir, outFile, imageDir);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
}
