#pragma once
// Markdown as a flat list of blocks with styled inline spans, parsed with md4c: what the viewer's
// Lesson panel draws with ImGui (headings, paragraphs, list items, code blocks, quotes, table
// rows, pictures). Raw HTML is not allowed in lessons: md4c passes it on as text.
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

struct MarkdownSpan {
    enum Style { Plain, Code, Emphasis, Strong, Link };
    Style style = Plain;
    std::string text;
};

struct MarkdownBlock {
    enum Kind { Heading, Paragraph, ListItem, Code, TableRow, Rule, Image };
    Kind kind = Paragraph;
    int level = 0;                      // Heading: 1-6; ListItem and Paragraph: list nesting (0 = none)
    bool quote = false;                 // inside a block quote
    std::string marker;                 // ListItem: "-" or "3."
    std::vector<MarkdownSpan> spans;    // Heading, Paragraph, ListItem; Image: its alt text
    std::string source;                 // Image: `![alt](SOURCE)` as written (a block of its own, text around it splits)
    std::string code;                   // Code: the text, lines ending in '\n'
    std::string info;                   // Code: the fence's info string ("glsl")
    std::vector<std::vector<MarkdownSpan>> cells;   // TableRow
    bool header = false;                // TableRow: a header row
    int columns = 0;                    // TableRow: the table's column count
    std::string plainText() const;      // spans (or cells, tab-separated) without styles
};

std::vector<MarkdownBlock> parseMarkdownBlocks(std::string_view markdown);

} // namespace raylab
