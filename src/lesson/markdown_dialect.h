#pragma once
// The Markdown of lessons, as every md4c reader here parses it: CommonMark with tables and
// strikethrough, raw HTML not recognised (it stays text).
#include <md4c.h>

namespace raylab {

inline MD_PARSER lessonMarkdownParser(int (*enterBlock)(MD_BLOCKTYPE, void*, void*), int (*leaveBlock)(MD_BLOCKTYPE, void*, void*),
                                      int (*enterSpan)(MD_SPANTYPE, void*, void*), int (*leaveSpan)(MD_SPANTYPE, void*, void*),
                                      int (*text)(MD_TEXTTYPE, const MD_CHAR*, MD_SIZE, void*)) {
    MD_PARSER parser{};
    parser.flags = MD_FLAG_TABLES | MD_FLAG_STRIKETHROUGH | MD_FLAG_NOHTML;
    parser.enter_block = enterBlock;
    parser.leave_block = leaveBlock;
    parser.enter_span = enterSpan;
    parser.leave_span = leaveSpan;
    parser.text = text;
    return parser;
}

} // namespace raylab
