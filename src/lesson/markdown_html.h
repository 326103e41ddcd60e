#pragma once
// Markdown to HTML through md4c's parser callbacks (Debian ships md4c-html separately): the
// handouts' body. CommonMark with tables and strikethrough; raw HTML is text, as in the viewer.
#include <functional>
#include <string>
#include <string_view>

namespace raylab {

// Maps an image's source as written (`![alt](SRC)`) to the URI the page uses; it may throw.
using ImageSource = std::function<std::string(const std::string& src)>;

std::string markdownToHtml(std::string_view markdown, const ImageSource& imageSource);

// `text` with & < > " escaped for HTML text and attribute values.
std::string htmlEscape(std::string_view text);

} // namespace raylab
