#include "lesson/markdown_html.h"

#include "lesson/markdown_dialect.h"
#include "lesson/section_marker.h"

#include <exception>

namespace raylab {
namespace {

struct Writer {
    std::string out;
    const ImageSource* imageSource = nullptr;
    int imageDepth = 0;                 // inside an image's alt text: text only, no tags
    std::exception_ptr error;           // an ImageSource failure, rethrown after md_parse
    std::size_t headingStart = 0;       // where the open heading's text starts in `out`
    void tag(std::string_view t) {
        if (imageDepth == 0) out += t;
    }
};

std::string attribute(const MD_ATTRIBUTE& a) {
    std::string s;
    for (unsigned i = 0; a.substr_offsets[i] < a.size; ++i) {
        const std::string_view part(a.text + a.substr_offsets[i], a.substr_offsets[i + 1] - a.substr_offsets[i]);
        s += a.substr_types[i] == MD_TEXT_ENTITY ? std::string(part) : htmlEscape(part);
    }
    return s;
}

std::string_view alignment(MD_ALIGN a) {
    switch (a) {
    case MD_ALIGN_LEFT: return " style=\"text-align:left\"";
    case MD_ALIGN_CENTER: return " style=\"text-align:center\"";
    case MD_ALIGN_RIGHT: return " style=\"text-align:right\"";
    default: return "";
    }
}

// The tag that opens (or closes) a block; "" for blocks without one.
std::string blockTag(MD_BLOCKTYPE type, void* detail, bool close) {
    const std::string slash = close ? "/" : "";
    auto pair = [&](const char* name, const char* after = "") { return "<" + slash + name + ">" + after; };
    switch (type) {
    case MD_BLOCK_QUOTE: return pair("blockquote", "\n");
    case MD_BLOCK_UL: return pair("ul", "\n");
    case MD_BLOCK_OL: {
        const unsigned start = static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start;
        return close || start == 1 ? pair("ol", "\n") : "<ol start=\"" + std::to_string(start) + "\">\n";
    }
    case MD_BLOCK_LI: return pair("li", close ? "\n" : "");
    case MD_BLOCK_HR: return close ? "" : "<hr>\n";
    case MD_BLOCK_H: return "<" + slash + "h" + std::to_string(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level) + (close ? ">\n" : ">");
    case MD_BLOCK_CODE: {
        const auto* d = static_cast<MD_BLOCK_CODE_DETAIL*>(detail);
        if (close) return "</code></pre>\n";
        return d->lang.size ? "<pre><code class=\"language-" + attribute(d->lang) + "\">" : std::string("<pre><code>");
    }
    case MD_BLOCK_P: return pair("p", close ? "\n" : "");
    case MD_BLOCK_TABLE: return pair("table", "\n");
    case MD_BLOCK_THEAD: return pair("thead", "\n");
    case MD_BLOCK_TBODY: return pair("tbody", "\n");
    case MD_BLOCK_TR: return pair("tr", close ? "\n" : "");
    case MD_BLOCK_TH:
    case MD_BLOCK_TD: {
        const char* name = type == MD_BLOCK_TH ? "th" : "td";
        if (close) return pair(name);
        return "<" + std::string(name) + std::string(alignment(static_cast<MD_BLOCK_TD_DETAIL*>(detail)->align)) + ">";
    }
    default: return "";   // the document, raw HTML (not allowed)
    }
}

int enterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    w.tag(blockTag(type, detail, false));
    if (type == MD_BLOCK_H) w.headingStart = w.out.size();
    return 0;
}

int leaveBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    // A lesson's role marker is for the loader, not the reader (escaping leaves `{#.}` as they are).
    if (type == MD_BLOCK_H) w.out.erase(w.headingStart + sectionMarkerStart(std::string_view(w.out).substr(w.headingStart)));
    w.tag(blockTag(type, detail, true));
    return 0;
}

// The tag of a span but an image; "" for spans without one.
std::string spanTag(MD_SPANTYPE type, void* detail, bool close) {
    const std::string slash = close ? "/" : "";
    switch (type) {
    case MD_SPAN_EM: return "<" + slash + "em>";
    case MD_SPAN_STRONG: return "<" + slash + "strong>";
    case MD_SPAN_CODE: return "<" + slash + "code>";
    case MD_SPAN_DEL: return "<" + slash + "del>";
    case MD_SPAN_A: return close ? "</a>" : "<a href=\"" + attribute(static_cast<MD_SPAN_A_DETAIL*>(detail)->href) + "\">";
    default: return "";
    }
}

int enterSpan(MD_SPANTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    if (type != MD_SPAN_IMG) {
        w.tag(spanTag(type, detail, false));
        return 0;
    }
    const auto* d = static_cast<MD_SPAN_IMG_DETAIL*>(detail);
    std::string uri;
    try {
        if (!w.error) uri = (*w.imageSource)(std::string(d->src.text, d->src.size));
    } catch (...) {
        w.error = std::current_exception();
    }
    w.tag("<img src=\"" + htmlEscape(uri) + "\" alt=\"");
    ++w.imageDepth;
    return 0;
}

int leaveSpan(MD_SPANTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    if (type != MD_SPAN_IMG) w.tag(spanTag(type, detail, true));
    else if (--w.imageDepth == 0) w.out += "\">";
    return 0;
}

int onText(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* user) {
    auto& w = *static_cast<Writer*>(user);
    const std::string_view t(text, size);
    switch (type) {
    case MD_TEXT_NULLCHAR: w.out += "\xEF\xBF\xBD"; break;   // U+FFFD, as CommonMark asks
    case MD_TEXT_BR: w.out += w.imageDepth ? " " : "<br>\n"; break;
    case MD_TEXT_SOFTBR: w.out += w.imageDepth ? " " : "\n"; break;
    case MD_TEXT_HTML: break;
    case MD_TEXT_ENTITY: w.out += t; break;
    default: w.out += htmlEscape(t); break;
    }
    return 0;
}

} // namespace

std::string htmlEscape(std::string_view text) {
    std::string s;
    s.reserve(text.size());
    for (const char ch : text) {
        switch (ch) {
        case '&': s += "&amp;"; break;
        case '<': s += "&lt;"; break;
        case '>': s += "&gt;"; break;
        case '"': s += "&quot;"; break;
        default: s += ch; break;
        }
    }
    return s;
}

std::string markdownToHtml(std::string_view markdown, const ImageSource& imageSource) {
    Writer w;
    w.imageSource = &imageSource;
    const MD_PARSER parser = lessonMarkdownParser(enterBlock, leaveBlock, enterSpan, leaveSpan, onText);
    md_parse(markdown.data(), MD_SIZE(markdown.size()), &parser, &w);
    if (w.error) std::rethrow_exception(w.error);
    return std::move(w.out);
}

} // namespace raylab
