#include "lesson/markdown_html.h"

#include <md4c.h>

#include <exception>

namespace raylab {
namespace {

struct Writer {
    std::string out;
    const ImageSource* imageSource = nullptr;
    int imageDepth = 0;                 // inside an image's alt text: text only, no tags
    std::exception_ptr error;           // an ImageSource failure, rethrown after md_parse
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

int enterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    switch (type) {
    case MD_BLOCK_DOC: break;
    case MD_BLOCK_QUOTE: w.tag("<blockquote>\n"); break;
    case MD_BLOCK_UL: w.tag("<ul>\n"); break;
    case MD_BLOCK_OL: {
        const unsigned start = static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start;
        w.tag(start == 1 ? std::string("<ol>\n") : "<ol start=\"" + std::to_string(start) + "\">\n");
        break;
    }
    case MD_BLOCK_LI: w.tag("<li>"); break;
    case MD_BLOCK_HR: w.tag("<hr>\n"); break;
    case MD_BLOCK_H: w.tag("<h" + std::to_string(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level) + ">"); break;
    case MD_BLOCK_CODE: {
        const auto* d = static_cast<MD_BLOCK_CODE_DETAIL*>(detail);
        w.tag(d->lang.size ? "<pre><code class=\"language-" + attribute(d->lang) + "\">" : std::string("<pre><code>"));
        break;
    }
    case MD_BLOCK_HTML: break;
    case MD_BLOCK_P: w.tag("<p>"); break;
    case MD_BLOCK_TABLE: w.tag("<table>\n"); break;
    case MD_BLOCK_THEAD: w.tag("<thead>\n"); break;
    case MD_BLOCK_TBODY: w.tag("<tbody>\n"); break;
    case MD_BLOCK_TR: w.tag("<tr>"); break;
    case MD_BLOCK_TH: w.tag("<th" + std::string(alignment(static_cast<MD_BLOCK_TD_DETAIL*>(detail)->align)) + ">"); break;
    case MD_BLOCK_TD: w.tag("<td" + std::string(alignment(static_cast<MD_BLOCK_TD_DETAIL*>(detail)->align)) + ">"); break;
    }
    return 0;
}

int leaveBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    switch (type) {
    case MD_BLOCK_DOC: break;
    case MD_BLOCK_QUOTE: w.tag("</blockquote>\n"); break;
    case MD_BLOCK_UL: w.tag("</ul>\n"); break;
    case MD_BLOCK_OL: w.tag("</ol>\n"); break;
    case MD_BLOCK_LI: w.tag("</li>\n"); break;
    case MD_BLOCK_HR: break;
    case MD_BLOCK_H: w.tag("</h" + std::to_string(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level) + ">\n"); break;
    case MD_BLOCK_CODE: w.tag("</code></pre>\n"); break;
    case MD_BLOCK_HTML: break;
    case MD_BLOCK_P: w.tag("</p>\n"); break;
    case MD_BLOCK_TABLE: w.tag("</table>\n"); break;
    case MD_BLOCK_THEAD: w.tag("</thead>\n"); break;
    case MD_BLOCK_TBODY: w.tag("</tbody>\n"); break;
    case MD_BLOCK_TR: w.tag("</tr>\n"); break;
    case MD_BLOCK_TH: w.tag("</th>"); break;
    case MD_BLOCK_TD: w.tag("</td>"); break;
    }
    return 0;
}

int enterSpan(MD_SPANTYPE type, void* detail, void* user) {
    auto& w = *static_cast<Writer*>(user);
    switch (type) {
    case MD_SPAN_EM: w.tag("<em>"); break;
    case MD_SPAN_STRONG: w.tag("<strong>"); break;
    case MD_SPAN_CODE: w.tag("<code>"); break;
    case MD_SPAN_DEL: w.tag("<del>"); break;
    case MD_SPAN_A: {
        const auto* d = static_cast<MD_SPAN_A_DETAIL*>(detail);
        w.tag("<a href=\"" + attribute(d->href) + "\">");
        break;
    }
    case MD_SPAN_IMG: {
        const auto* d = static_cast<MD_SPAN_IMG_DETAIL*>(detail);
        std::string uri;
        try {
            if (!w.error) uri = (*w.imageSource)(std::string(d->src.text, d->src.size));
        } catch (...) {
            w.error = std::current_exception();
        }
        w.tag("<img src=\"" + htmlEscape(uri) + "\" alt=\"");
        ++w.imageDepth;
        break;
    }
    default: break;
    }
    return 0;
}

int leaveSpan(MD_SPANTYPE type, void*, void* user) {
    auto& w = *static_cast<Writer*>(user);
    switch (type) {
    case MD_SPAN_EM: w.tag("</em>"); break;
    case MD_SPAN_STRONG: w.tag("</strong>"); break;
    case MD_SPAN_CODE: w.tag("</code>"); break;
    case MD_SPAN_DEL: w.tag("</del>"); break;
    case MD_SPAN_A: w.tag("</a>"); break;
    case MD_SPAN_IMG:
        if (--w.imageDepth == 0) w.out += "\">";
        break;
    default: break;
    }
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
    MD_PARSER parser{};
    parser.flags = MD_FLAG_TABLES | MD_FLAG_STRIKETHROUGH | MD_FLAG_NOHTML;
    parser.enter_block = enterBlock;
    parser.leave_block = leaveBlock;
    parser.enter_span = enterSpan;
    parser.leave_span = leaveSpan;
    parser.text = onText;
    md_parse(markdown.data(), MD_SIZE(markdown.size()), &parser, &w);
    if (w.error) std::rethrow_exception(w.error);
    return std::move(w.out);
}

} // namespace raylab
