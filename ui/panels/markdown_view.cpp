#include "panels/markdown_view.h"

#include "io/image_io.h"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <unordered_map>

namespace raylab::ui {
namespace {

struct Fonts {
    ImFont* regular = nullptr;
    ImFont* bold = nullptr;
    ImFont* italic = nullptr;
    ImFont* mono = nullptr;
};
Fonts g_fonts;

ImFont* fontFor(MarkdownSpan::Style s) {
    switch (s) {
    case MarkdownSpan::Code: return g_fonts.mono;
    case MarkdownSpan::Emphasis: return g_fonts.italic;
    case MarkdownSpan::Strong: return g_fonts.bold;
    default: return g_fonts.regular;
    }
}

// Pushes a font when there is one (ImGui::PushFont(nullptr) would mean the default font).
struct FontScope {
    bool pushed;
    explicit FontScope(ImFont* f) : pushed(f != nullptr) {
        if (pushed) ImGui::PushFont(f);
    }
    ~FontScope() {
        if (pushed) ImGui::PopFont();
    }
};

ImVec4 spanColour(MarkdownSpan::Style s, bool quote) {
    switch (s) {
    case MarkdownSpan::Code: return ImVec4(0.95f, 0.75f, 0.45f, 1.0f);
    case MarkdownSpan::Emphasis: return ImVec4(0.70f, 0.85f, 1.0f, 1.0f);
    case MarkdownSpan::Strong: return ImVec4(1.0f, 1.0f, 0.75f, 1.0f);
    case MarkdownSpan::Link: return ImVec4(0.45f, 0.70f, 1.0f, 1.0f);
    default: return quote ? ImVec4(0.72f, 0.72f, 0.72f, 1.0f) : ImGui::GetStyleColorVec4(ImGuiCol_Text);
    }
}

// Word-wraps styled spans at the window's right edge (ImGui's own wrapping takes one style).
void drawSpans(const std::vector<MarkdownSpan>& spans, bool quote) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    const float space = ImGui::CalcTextSize(" ").x;
    bool lineHasWords = false;
    bool pendingSpace = false;
    for (const MarkdownSpan& span : spans) {
        const ImVec4 colour = spanColour(span.style, quote);
        const FontScope font(fontFor(span.style));
        std::size_t i = 0;
        const std::string& t = span.text;
        while (i < t.size()) {
            if (t[i] == ' ' || t[i] == '\t' || t[i] == '\n') {
                pendingSpace = true;
                ++i;
                continue;
            }
            std::size_t end = t.find_first_of(" \t\n", i);
            if (end == std::string::npos) end = t.size();
            const std::string word = t.substr(i, end - i);
            const float w = ImGui::CalcTextSize(word.c_str()).x;
            if (lineHasWords) {
                const float x = ImGui::GetItemRectMax().x + (pendingSpace ? space : 0.0f);
                if (x + w <= right) ImGui::SameLine(0.0f, pendingSpace ? space : 0.0f);
            }
            ImGui::TextColored(colour, "%s", word.c_str());
            if (span.style == MarkdownSpan::Strong && !g_fonts.bold) {   // faux bold: the word again, one pixel right
                const ImVec2 p = ImGui::GetItemRectMin();
                ImGui::GetWindowDrawList()->AddText(ImVec2(p.x + 1.0f, p.y), ImGui::GetColorU32(colour), word.c_str());
            }
            lineHasWords = true;
            pendingSpace = false;
            i = end;
        }
    }
    if (!lineHasWords) ImGui::NewLine();
}

void drawTable(const std::vector<MarkdownBlock>& blocks, std::size_t& i) {
    const int columns = std::max(1, blocks[i].columns);
    const std::string id = "##table" + std::to_string(i);   // callers PushID per document
    if (ImGui::BeginTable(id.c_str(), columns, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        for (; i < blocks.size() && blocks[i].kind == MarkdownBlock::TableRow; ++i) {
            ImGui::TableNextRow(blocks[i].header ? ImGuiTableRowFlags_Headers : 0);
            for (int c = 0; c < columns; ++c) {
                ImGui::TableSetColumnIndex(c);
                if (c < int(blocks[i].cells.size())) {
                    ImGui::PushTextWrapPos(0.0f);
                    std::string text;
                    for (const MarkdownSpan& s : blocks[i].cells[std::size_t(c)]) text += s.text;
                    ImGui::TextUnformatted(text.c_str());
                    ImGui::PopTextWrapPos();
                }
            }
        }
        ImGui::EndTable();
    } else {
        while (i < blocks.size() && blocks[i].kind == MarkdownBlock::TableRow) ++i;
    }
    --i;   // the caller's loop steps past the last row
}

// A picture file read once: its size and texture, or why it cannot be shown.
struct Picture {
    int width = 0, height = 0;
    std::vector<float> rgba;   // kept until a GL context takes it
    GLuint texture = 0;
    std::string error;
};

// Textures need the viewer's GL context: ImGui's OpenGL backend is installed only where there is one.
bool haveGlContext() {
    const char* backend = ImGui::GetIO().BackendRendererName;
    return backend && std::strcmp(backend, "imgui_impl_opengl3") == 0 && GLAD_GL_VERSION_1_1;
}

Picture& picture(const std::filesystem::path& file) {
    static std::map<std::filesystem::path, Picture> pictures;
    auto [it, fresh] = pictures.try_emplace(file);
    Picture& p = it->second;
    if (fresh) {
        try {
            Image image = readImage(file);
            p.width = image.width;
            p.height = image.height;
            p.rgba = std::move(image.rgba);
        } catch (const std::exception& e) {
            p.error = e.what();
        }
    }
    if (p.error.empty() && p.texture == 0 && haveGlContext()) {
        glGenTextures(1, &p.texture);
        glBindTexture(GL_TEXTURE_2D, p.texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, p.width, p.height, 0, GL_RGBA, GL_FLOAT, p.rgba.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        p.rgba = {};
    }
    return p;
}

// The picture at the panel's width (its top row first, as OpenImageIO reads it); a frame with its
// alt text where no texture can be made, the located reason where the file cannot be read.
void drawPicture(const MarkdownBlock& b, const Lesson* lesson) {
    std::string alt;
    for (const MarkdownSpan& s : b.spans) alt += s.text;
    std::string where = lesson ? lesson->file.string() : std::string("markdown");
    if (lesson) {
        const auto it = std::find_if(lesson->pictures.begin(), lesson->pictures.end(),
                                     [&](const LessonPicture& p) { return p.source == b.source; });
        if (it != lesson->pictures.end() && it->line > 0) where += ":" + std::to_string(it->line);
    }
    auto problem = [&](const std::string& why) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s: cannot show the picture '%s': %s", where.c_str(),
                           b.source.c_str(), why.c_str());
        ImGui::PopTextWrapPos();
    };
    if (!lesson) return problem("pictures are files relative to a lesson, and there is none");
    const Picture& p = picture(lesson->picturePath(b.source));
    if (!p.error.empty()) return problem(p.error);
    const float width = std::max(1.0f, ImGui::GetContentRegionAvail().x);
    const ImVec2 size(width, width * float(p.height) / float(std::max(1, p.width)));
    if (p.texture) {
        ImGui::Image(ImTextureID(std::uintptr_t(p.texture)), size);
    } else {
        const ImVec2 at = ImGui::GetCursorScreenPos();
        ImGui::GetWindowDrawList()->AddRect(at, ImVec2(at.x + size.x, at.y + size.y), IM_COL32(128, 128, 128, 255));
        ImGui::TextDisabled("[picture: %s]", alt.c_str());
        ImGui::SetCursorScreenPos(at);
        ImGui::Dummy(size);
    }
    if (!alt.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", alt.c_str());
}

} // namespace

void drawMarkdown(const std::vector<MarkdownBlock>& blocks, const Lesson* lesson) {
    const float indentStep = ImGui::GetFontSize() * 1.2f;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const MarkdownBlock& b = blocks[i];
        const float indent = indentStep * float(b.level) + (b.quote ? indentStep : 0.0f);
        if (indent > 0.0f) ImGui::Indent(indent);
        switch (b.kind) {
        case MarkdownBlock::Heading: {
            ImGui::Spacing();
            const ImVec4 colour = b.level <= 2 ? ImVec4(1.0f, 0.85f, 0.4f, 1.0f) : ImVec4(0.9f, 0.8f, 0.55f, 1.0f);
            const FontScope font(g_fonts.bold);
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(colour, "%s", b.plainText().c_str());
            ImGui::PopTextWrapPos();
            if (b.level <= 2) ImGui::Separator();
            break;
        }
        case MarkdownBlock::Paragraph: drawSpans(b.spans, b.quote); break;
        case MarkdownBlock::ListItem: {
            if (b.marker == "-") {
                ImGui::Bullet();   // the default font has no • glyph
            } else {
                ImGui::TextUnformatted(b.marker.c_str());
                ImGui::SameLine();
            }
            ImGui::BeginGroup();
            drawSpans(b.spans, b.quote);
            ImGui::EndGroup();
            break;
        }
        case MarkdownBlock::Code: {
            const FontScope font(g_fonts.mono);
            std::string code = b.code;
            while (!code.empty() && code.back() == '\n') code.pop_back();
            const ImVec2 size = ImGui::CalcTextSize(code.c_str());
            const ImVec2 p = ImGui::GetCursorScreenPos();
            const ImVec2 pad = ImGui::GetStyle().FramePadding;
            ImGui::GetWindowDrawList()->AddRectFilled(
                p, ImVec2(p.x + std::max(size.x, ImGui::GetContentRegionAvail().x), p.y + size.y + 2 * pad.y),
                IM_COL32(20, 20, 24, 255), 3.0f);
            ImGui::SetCursorScreenPos(ImVec2(p.x + pad.x, p.y + pad.y));
            ImGui::TextColored(ImVec4(0.8f, 0.9f, 0.8f, 1.0f), "%s", code.c_str());
            ImGui::Dummy(ImVec2(0.0f, pad.y));
            break;
        }
        case MarkdownBlock::TableRow: drawTable(blocks, i); break;
        case MarkdownBlock::Rule: ImGui::Separator(); break;
        case MarkdownBlock::Image: drawPicture(b, lesson); break;
        }
        if (indent > 0.0f) ImGui::Unindent(indent);
    }
}

void loadLessonFonts(float pixels) {
    const std::string dir = "/usr/share/fonts/truetype/dejavu/";
    auto exists = [](const std::string& f) { return std::filesystem::exists(f); };
    if (!exists(dir + "DejaVuSans.ttf")) return;
    ImGuiIO& io = ImGui::GetIO();
    if (io.Fonts->Fonts.empty()) io.Fonts->AddFontDefault();   // the UI's own font stays the default
    // Latin-1 and Latin Extended-A, Greek, general punctuation (– — “ ” …), super- and subscripts,
    // arrows, mathematical operators (≤ ∞ ∫ ∑ √ ≈), geometric shapes (•).
    static const ImWchar ranges[] = {0x0020, 0x017F, 0x0370, 0x03FF, 0x2000, 0x209F, 0x2190, 0x22FF, 0x25A0, 0x25FF, 0};
    auto add = [&](const char* file) -> ImFont* {
        return exists(dir + file) ? io.Fonts->AddFontFromFileTTF((dir + file).c_str(), pixels, nullptr, ranges) : nullptr;
    };
    g_fonts.regular = add("DejaVuSans.ttf");
    g_fonts.bold = add("DejaVuSans-Bold.ttf");
    g_fonts.italic = add("DejaVuSans-Oblique.ttf");
    g_fonts.mono = add("DejaVuSansMono.ttf");
}

ImFont* lessonFont() { return g_fonts.regular; }

void drawMarkdown(std::string_view markdown, const Lesson* lesson) {
    // Lesson texts do not change between frames: parse each once (the cache is dropped when large).
    static std::unordered_map<std::string, std::vector<MarkdownBlock>> cache;
    auto it = cache.find(std::string(markdown));
    if (it == cache.end()) {
        if (cache.size() > 512) cache.clear();
        it = cache.emplace(std::string(markdown), parseMarkdownBlocks(markdown)).first;
    }
    drawMarkdown(it->second, lesson);
}

} // namespace raylab::ui
