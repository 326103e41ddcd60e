#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <tuple>
#include <vector>

namespace raylab {
namespace {

// The lines of an OBJ text split at "\n", "\r\n" or "\r" (tinyobjloader accepts all three).
std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n' && text[i] != '\r') continue;
        lines.push_back(text.substr(start, i - start));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        start = i + 1;
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

// Space- or tab-separated words, up to a '#' comment.
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        if (i == line.size() || line[i] == '#') break;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        out.push_back(line.substr(start, i - start));
    }
    return out;
}

// A word as it may be shown in a message (short, printable).
std::string shown(std::string_view word) {
    std::string s;
    for (char c : word.substr(0, 24)) s += (c >= 0x20 && c < 0x7f) ? c : '?';
    return "'" + s + (word.size() > 24 ? "...'" : "'");
}

// OBJ counts from 1; negative indices count back from the last element defined so far.
struct IndexKind {
    const char* singular;
    const char* plural;
    long long total = 0;   // in the whole file
    long long sofar = 0;   // before the current line
};

// tinyobjloader reads what it can and zeroes or skips the rest, so the text is checked first,
// line by line, to reject every malformed number, index and face with its line number.
class ObjChecker {
public:
    explicit ObjChecker(const std::string& name) : name_(name) {}

    void check(const std::vector<std::string_view>& lines) {
        for (std::string_view line : lines) {
            const std::vector<std::string_view> w = words(line);
            if (w.empty()) continue;
            if (w[0] == "v") ++positions_.total;
            else if (w[0] == "vn") ++normals_.total;
            else if (w[0] == "vt") ++uvs_.total;
        }
        for (std::size_t n = 0; n < lines.size(); ++n) {
            line_ = n + 1;
            const std::vector<std::string_view> w = words(lines[n]);
            if (w.empty()) continue;
            if (w[0] == "v") {
                numbers(w, 3, 7, "a vertex position");   // x y z [w] or x y z r g b [a]
                ++positions_.sofar;
            } else if (w[0] == "vn") {
                numbers(w, 3, 3, "a normal");
                ++normals_.sofar;
            } else if (w[0] == "vt") {
                numbers(w, 1, 3, "a texture coordinate");
                ++uvs_.sofar;
            } else if (w[0] == "f") {
                face(w);
            }
        }
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw ObjError(name_ + ":" + std::to_string(line_) + ": " + what);
    }

    void numbers(const std::vector<std::string_view>& w, std::size_t least, std::size_t most, const char* what) const {
        const std::size_t n = w.size() - 1;
        if (n < least || n > most)
            fail(std::string(what) + " needs " + std::to_string(least) +
                 (least == most ? "" : " to " + std::to_string(most)) + " numbers, got " + std::to_string(n));
        for (std::size_t i = 1; i < w.size(); ++i) number(w[i], what);
    }

    void number(std::string_view word, const char* what) const {
        std::string_view t = word;
        if (!t.empty() && t[0] == '+') t.remove_prefix(1);
        double x = 0.0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
        if (end != t.data() + t.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
            fail(std::string(what) + ": " + shown(word) + " is not a number");
        if (ec == std::errc::result_out_of_range)   // underflow to 0 is harmless, overflow is not
            x = std::strtod(std::string(t).c_str(), nullptr);
        if (!std::isfinite(x) || std::abs(x) > double(std::numeric_limits<float>::max()))
            fail(std::string(what) + ": " + shown(word) + " is not a finite 32-bit float");
    }

    void face(const std::vector<std::string_view>& w) const {
        if (w.size() < 4) fail("a face needs at least 3 vertices, got " + std::to_string(w.size() - 1));
        for (std::size_t i = 1; i < w.size(); ++i) {
            // v, v/vt, v//vn or v/vt/vn
            std::string_view parts[3];
            std::size_t count = 0;
            std::string_view rest = w[i];
            while (true) {
                const std::size_t slash = rest.find('/');
                if (count == 3) fail("face vertex " + shown(w[i]) + " has more than 3 parts (v/vt/vn)");
                parts[count++] = rest.substr(0, slash);
                if (slash == std::string_view::npos) break;
                rest.remove_prefix(slash + 1);
            }
            if (parts[0].empty() || (count == 2 && parts[1].empty()) || (count == 3 && parts[2].empty()))
                fail("face vertex " + shown(w[i]) + " is incomplete (expected v, v/vt, v//vn or v/vt/vn)");
            index(parts[0], w[i], positions_);
            if (count >= 2 && !parts[1].empty()) index(parts[1], w[i], uvs_);
            if (count == 3) index(parts[2], w[i], normals_);
        }
    }

    void index(std::string_view text, std::string_view word, const IndexKind& kind) const {
        long long i = 0;
        std::string_view t = text;
        if (!t.empty() && t[0] == '+') t.remove_prefix(1);
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), i);
        if (ec != std::errc() || end != t.data() + t.size())
            fail("face vertex " + shown(word) + ": " + kind.singular + " index " + shown(text) + " is not an integer");
        if (i == 0) fail("face vertex " + shown(word) + ": " + kind.singular + " index 0 (OBJ counts from 1)");
        const bool ok = i > 0 ? i <= kind.total : -i <= kind.sofar;
        if (!ok)
            fail("face vertex " + shown(word) + ": " + kind.singular + " index " + std::to_string(i) +
                 " is out of range (" + std::to_string(i > 0 ? kind.total : kind.sofar) + " " + kind.plural +
                 (i > 0 ? "" : " so far") + ")");
    }

    const std::string& name_;
    std::size_t line_ = 0;
    IndexKind positions_{"position", "positions"};
    IndexKind normals_{"normal", "normals"};
    IndexKind uvs_{"texture coordinate", "texture coordinates"};
};

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

// tinyobjloader's warnings about geometry become errors; those about materials and group names
// (which raylab does not read) are dropped, as scenes/FORMAT.md says.
void rejectWarnings(const std::string& name, const std::string& warnings) {
    std::istringstream in(warnings);
    for (std::string line; std::getline(in, line);) {
        line = trimmed(line);
        if (line.empty() || line.rfind("material [", 0) == 0 || line.rfind("Empty group name", 0) == 0) continue;
        throw ObjError(name + ": " + line);
    }
}

} // namespace

Mesh loadObj(const std::filesystem::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw ObjError(name + ": cannot read: no such file");
    std::ifstream in(file, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw ObjError(name + ": cannot read");
    ObjChecker(name).check(splitLines(text));

    tinyobj::attrib_t a;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    std::istringstream stream(text);
    // No material reader: mtllib is skipped (the scene assigns the material).
    bool parsed = false;
    try {
        parsed = tinyobj::LoadObj(&a, &shapes, &materials, &warn, &err, &stream, nullptr, true, false);
    } catch (const std::exception& e) {
        throw ObjError(name + ": cannot parse: " + e.what());
    }
    if (!parsed) {
        err = trimmed(err);
        throw ObjError(name + ": " + (err.empty() ? std::string("cannot parse") : err));
    }
    rejectWarnings(name, warn);

    Mesh mesh;
    std::map<std::tuple<int, int, int>, unsigned> merged;   // (v, vn, vt) → vertex
    bool anyNormal = false, anyUv = false, missingNormal = false, missingUv = false;
    for (const tinyobj::shape_t& shape : shapes) {
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            anyNormal |= i.normal_index >= 0;
            anyUv |= i.texcoord_index >= 0;
            missingNormal |= i.normal_index < 0;
            missingUv |= i.texcoord_index < 0;
        }
    }
    const bool useNormals = anyNormal && !missingNormal;   // all or nothing, per mesh
    const bool useUvs = anyUv && !missingUv;
    // The checker has bounded every index; these guard the reads all the same.
    auto inside = [&name](int index, std::size_t width, const std::vector<tinyobj::real_t>& list, const char* what) {
        if (index < 0 || width * std::size_t(index) + width > list.size())
            throw ObjError(name + ": a face refers to " + what + " " + std::to_string(index + 1) + ", which does not exist");
        return width * std::size_t(index);
    };
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t f = 0; f + 2 < idx.size(); f += 3) {
            glm::uvec3 tri;
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& i = idx[f + std::size_t(k)];
                const auto key = std::make_tuple(i.vertex_index, useNormals ? i.normal_index : -1,
                                                 useUvs ? i.texcoord_index : -1);
                auto [it, inserted] = merged.try_emplace(key, unsigned(mesh.positions.size()));
                if (inserted) {
                    const std::size_t v = inside(i.vertex_index, 3, a.vertices, "position");
                    mesh.positions.emplace_back(a.vertices[v], a.vertices[v + 1], a.vertices[v + 2]);
                    if (useNormals) {
                        const std::size_t n = inside(i.normal_index, 3, a.normals, "normal");
                        mesh.normals.emplace_back(a.normals[n], a.normals[n + 1], a.normals[n + 2]);
                    }
                    if (useUvs) {
                        const std::size_t t = inside(i.texcoord_index, 2, a.texcoords, "texture coordinate");
                        mesh.uvs.emplace_back(a.texcoords[t], a.texcoords[t + 1]);
                    }
                }
                tri[k] = it->second;
            }
            mesh.triangles.push_back(tri);
        }
    }
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw ObjError(name + ": a vertex position is not a finite number");
    if (mesh.triangles.empty()) throw ObjError(name + ": contains no faces");
    return mesh;
}

} // namespace raylab
