#pragma once
// A repository in a scratch folder holding one English lesson and a Dutch edition of it made by
// rule (Dutch headings and title, `Language: nl`, pictures as ../pictures/), its scenes and
// pictures linked to the source tree's: what the drift test, raylab-lesson --lang and the viewer's
// --lang are tested on while lessons/nl/ may be incomplete. The prose stays English: the
// editions' contract (lessons/README.md) is about structure, and that is what is tested.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace raylab::test {

struct DutchLessonFixture {
    std::filesystem::path root;      // the scratch repository
    std::filesystem::path english;   // root/lessons/NAME
    std::filesystem::path dutch;     // root/lessons/nl/NAME
};

// The Dutch edition of an English lesson's text, by rule; `edit` then changes what a test needs.
inline std::string dutchEditionOf(const std::string& english) {
    static const std::pair<const char*, const char*> headings[] = {
        {"Learning goals", "Leerdoelen"}, {"Questions", "Vragen"}, {"Exercise", "Opdracht"},
        {"Write it yourself", "Schrijf het zelf"}, {"Going further", "Verder"},
        {"Teacher's notes", "Aantekeningen voor de docent"}, {"Sources", "Bronnen"}};
    std::istringstream in(english);
    std::string out, line;
    bool fence = false;
    while (std::getline(in, line)) {
        if (line.rfind("```", 0) == 0) fence = !fence;
        if (!fence) {
            if (line.rfind("# Lesson ", 0) == 0) line = "# Les " + line.substr(9);
            if (line.rfind("## Step ", 0) == 0) line = "## Stap " + line.substr(8);
            for (const auto& [en, nl] : headings)
                if (line.rfind("## " + std::string(en) + " {#", 0) == 0) line = "## " + std::string(nl) + line.substr(3 + std::strlen(en));
            line = std::regex_replace(line, std::regex(R"(\]\(pictures/)"), "](../pictures/");
        }
        out += line + "\n";
        if (!fence && line.rfind("Minutes:", 0) == 0) out += "\nLanguage: nl\n";
    }
    return out;
}

inline std::string readLessonText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Makes `dir` such a repository for lessons/NAME of the source tree (replacing what was there).
inline DutchLessonFixture makeDutchLessonFixture(const std::filesystem::path& dir, const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path src = RAYLAB_SOURCE_DIR;
    fs::remove_all(dir);
    fs::create_directories(dir / "lessons" / "nl");
    fs::create_directory_symlink(src / "scenes", dir / "scenes");
    fs::create_directory_symlink(src / "lessons" / "pictures", dir / "lessons" / "pictures");
    DutchLessonFixture f{dir, dir / "lessons" / name, dir / "lessons" / "nl" / name};
    fs::copy_file(src / "lessons" / name, f.english);
    std::ofstream(f.dutch, std::ios::binary) << dutchEditionOf(readLessonText(f.english));
    return f;
}

} // namespace raylab::test
