#pragma once
// Markdown drawn with Dear ImGui 1.86 (one font): headings by colour and a rule, paragraphs and
// list items word-wrapped with styled spans (code, emphasis, strong, links by colour), code blocks
// on a dark background, tables with ImGui's tables, block quotes indented in grey, pictures scaled
// to the panel's width.
#include "lesson/lesson.h"
#include "lesson/markdown_blocks.h"

#include <string_view>
#include <vector>

struct ImFont;

namespace raylab::ui {

// Lessons use DejaVu Sans (regular, bold, oblique) and DejaVu Sans Mono when installed
// (fonts-dejavu-core): Greek, arrows and maths symbols, real bold and italics. Call once after
// ImGui::CreateContext and before the first frame; without the files the default font is used.
void loadLessonFonts(float pixels = 15.0f);
// The lesson font, or null (then the default font): push it around lesson text.
ImFont* lessonFont();

// Pictures are files relative to `lesson`'s folder (none without a lesson), read with
// OpenImageIO once and drawn through the ImGui OpenGL backend's textures; one that cannot be read
// shows "LESSON:LINE: cannot show the picture ..." in its place.
void drawMarkdown(const std::vector<MarkdownBlock>& blocks, const Lesson* lesson = nullptr);
void drawMarkdown(std::string_view markdown, const Lesson* lesson = nullptr);   // parses (md4c) and draws

} // namespace raylab::ui
