#include "lesson/markdown_blocks.h"

#include "lesson/markdown_dialect.h"
#include "lesson/section_marker.h"

#include <algorithm>

namespace raylab {
namespace {

struct Builder {
    std::vector<MarkdownBlock> blocks;
    MarkdownBlock* current = nullptr;   // the block receiving text
    std::vector<MarkdownSpan::Style> styles;
    std::vector<int> listCounters;      // per open list: next number, or -1 for bullets
    int quoteDepth = 0;
    int columns = 0;
    bool inHead = false;
    bool inCell = false;
    bool itemFresh = false;             // the open list item has no paragraph yet
    int imageDepth = 0;                 // inside an image's alt text

    MarkdownBlock& open(MarkdownBlock::Kind kind) {
        MarkdownBlock b;
        b.kind = kind;
        b.quote = quoteDepth > 0;
        b.level = int(listCounters.size());
        blocks.push_back(std::move(b));
        current = &blocks.back();
        return *current;
    }
    // The innermost span decides, code over link over strong over emphasis.
    static int rank(MarkdownSpan::Style x) {
        switch (x) {
        case MarkdownSpan::Code: return 4;
        case MarkdownSpan::Link: return 3;
        case MarkdownSpan::Strong: return 2;
        case MarkdownSpan::Emphasis: return 1;
        default: return 0;
        }
    }
    MarkdownSpan::Style style() const {
        MarkdownSpan::Style s = MarkdownSpan::Plain;
        for (auto t : styles)
            if (rank(t) > rank(s)) s = t;
        return s;
    }
    // A picture is a block of its own: it takes over an empty paragraph, or follows the text so far.
    void openImage(std::string source) {
        if (current && current->kind == MarkdownBlock::Paragraph && current->spans.empty()) current->kind = MarkdownBlock::Image;
        else open(MarkdownBlock::Image);
        current->source = std::move(source);
    }
    void text(std::string_view t) {
        if (!current) return;
        if (current->kind == MarkdownBlock::Image && imageDepth == 0) open(MarkdownBlock::Paragraph);   // text after a picture
        if (current->kind == MarkdownBlock::Code) {
            current->code.append(t);
            return;
        }
        std::vector<MarkdownSpan>* spans = &current->spans;
        if (current->kind == MarkdownBlock::TableRow) {
            if (current->cells.empty()) current->cells.emplace_back();
            spans = &current->cells.back();
        }
        const auto s = style();
        if (spans->empty() || spans->back().style != s) spans->push_back(MarkdownSpan{s, ""});
        spans->back().text.append(t);
    }
};

int enterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    auto& b = *static_cast<Builder*>(user);
    switch (type) {
    case MD_BLOCK_H: b.open(MarkdownBlock::Heading).level = int(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level); break;
    case MD_BLOCK_P:
        if (b.itemFresh) b.itemFresh = false;   // the item's first paragraph is the item's text
        else b.open(MarkdownBlock::Paragraph);
        break;
    case MD_BLOCK_UL: b.listCounters.push_back(-1); break;
    case MD_BLOCK_OL: b.listCounters.push_back(int(static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start)); break;
    case MD_BLOCK_LI: {
        MarkdownBlock& item = b.open(MarkdownBlock::ListItem);
        int& n = b.listCounters.back();
        item.marker = n < 0 ? "-" : std::to_string(n++) + ".";
        b.itemFresh = true;
        break;
    }
    case MD_BLOCK_CODE: {
        MarkdownBlock& code = b.open(MarkdownBlock::Code);
        const auto* d = static_cast<MD_BLOCK_CODE_DETAIL*>(detail);
        if (d->info.text) code.info.assign(d->info.text, d->info.size);
        b.itemFresh = false;
        break;
    }
    case MD_BLOCK_QUOTE: ++b.quoteDepth; break;
    case MD_BLOCK_HR: b.open(MarkdownBlock::Rule); break;
    case MD_BLOCK_TABLE: b.columns = int(static_cast<MD_BLOCK_TABLE_DETAIL*>(detail)->col_count); break;
    case MD_BLOCK_THEAD: b.inHead = true; break;
    case MD_BLOCK_TR: {
        MarkdownBlock& row = b.open(MarkdownBlock::TableRow);
        row.header = b.inHead;
        row.columns = b.columns;
        break;
    }
    case MD_BLOCK_TH:
    case MD_BLOCK_TD:
        if (b.current && b.current->kind == MarkdownBlock::TableRow) b.current->cells.emplace_back();
        b.inCell = true;
        break;
    default: break;
    }
    return 0;
}

int leaveBlock(MD_BLOCKTYPE type, void*, void* user) {
    auto& b = *static_cast<Builder*>(user);
    switch (type) {
    case MD_BLOCK_H:   // a lesson's role marker is for the loader, not the reader
        if (b.current && !b.current->spans.empty()) {
            std::string& last = b.current->spans.back().text;
            last.erase(sectionMarkerStart(last));
            if (last.empty()) b.current->spans.pop_back();
        }
        break;
    case MD_BLOCK_UL:
    case MD_BLOCK_OL: b.listCounters.pop_back(); break;
    case MD_BLOCK_LI: b.itemFresh = false; break;
    case MD_BLOCK_QUOTE: --b.quoteDepth; break;
    case MD_BLOCK_THEAD: b.inHead = false; break;
    case MD_BLOCK_TH:
    case MD_BLOCK_TD: b.inCell = false; break;
    default: break;
    }
    return 0;
}

MarkdownSpan::Style spanStyle(MD_SPANTYPE type) {
    switch (type) {
    case MD_SPAN_CODE: return MarkdownSpan::Code;
    case MD_SPAN_EM: return MarkdownSpan::Emphasis;
    case MD_SPAN_STRONG: return MarkdownSpan::Strong;
    case MD_SPAN_A: return MarkdownSpan::Link;
    default: return MarkdownSpan::Plain;
    }
}

int enterSpan(MD_SPANTYPE type, void* detail, void* user) {
    auto& b = *static_cast<Builder*>(user);
    if (type == MD_SPAN_IMG && b.imageDepth++ == 0) {
        const MD_ATTRIBUTE& src = static_cast<MD_SPAN_IMG_DETAIL*>(detail)->src;
        b.openImage(std::string(src.text, src.size));
    }
    b.styles.push_back(spanStyle(type));
    return 0;
}

int leaveSpan(MD_SPANTYPE type, void*, void* user) {
    auto& b = *static_cast<Builder*>(user);
    if (type == MD_SPAN_IMG) --b.imageDepth;
    if (!b.styles.empty()) b.styles.pop_back();
    return 0;
}

int onText(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* user) {
    auto& b = *static_cast<Builder*>(user);
    switch (type) {
    case MD_TEXT_NULLCHAR: return 0;
    case MD_TEXT_HTML: return 0;
    case MD_TEXT_BR:
    case MD_TEXT_SOFTBR: b.text(" "); return 0;
    default: b.text(std::string_view(text, size)); return 0;
    }
}

} // namespace

std::string MarkdownBlock::plainText() const {
    std::string s;
    if (kind == Code) return code;
    if (kind == TableRow) {
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i) s += '\t';
            for (const MarkdownSpan& sp : cells[i]) s += sp.text;
        }
        return s;
    }
    for (const MarkdownSpan& sp : spans) s += sp.text;
    return s;
}

std::vector<MarkdownBlock> parseMarkdownBlocks(std::string_view markdown) {
    Builder b;
    const MD_PARSER parser = lessonMarkdownParser(enterBlock, leaveBlock, enterSpan, leaveSpan, onText);
    // `current` points into the vector: open() re-points it after every append.
    md_parse(markdown.data(), MD_SIZE(markdown.size()), &parser, &b);
    return std::move(b.blocks);
}

} // namespace raylab
