// Markdown as the Lesson panel draws it: blocks and styled spans from md4c.
#include "lesson/markdown_blocks.h"

#include <gtest/gtest.h>

using namespace raylab;

TEST(MarkdownBlocks, HeadingsParagraphsListsCodeAndTables) {
    const auto blocks = parseMarkdownBlocks("### Sub\n\nSome *em* and **strong** and `code` text\non two lines.\n\n"
                                            "- one\n- two `x`\n  - nested\n\n3. three\n4. four\n\nText.\n\n"
                                            "    indented = code\n\n```glsl\nvec3 a;\n```\n\n"
                                            "| a | b |\n|---|---|\n| 1 | 2 |\n\n> quoted\n\n---\n");
    ASSERT_EQ(blocks.size(), 14u) << blocks.back().plainText();
    EXPECT_EQ(blocks[0].kind, MarkdownBlock::Heading);
    EXPECT_EQ(blocks[0].level, 3);
    EXPECT_EQ(blocks[0].plainText(), "Sub");
    const MarkdownBlock& p = blocks[1];
    EXPECT_EQ(p.kind, MarkdownBlock::Paragraph);
    EXPECT_EQ(p.plainText(), "Some em and strong and code text on two lines.");
    ASSERT_GE(p.spans.size(), 6u);
    EXPECT_EQ(p.spans[1].style, MarkdownSpan::Emphasis);
    EXPECT_EQ(p.spans[3].style, MarkdownSpan::Strong);
    EXPECT_EQ(p.spans[5].style, MarkdownSpan::Code);
    EXPECT_EQ(p.spans[5].text, "code");
    EXPECT_EQ(blocks[2].kind, MarkdownBlock::ListItem);
    EXPECT_EQ(blocks[2].marker, "-");
    EXPECT_EQ(blocks[2].level, 1);
    EXPECT_EQ(blocks[3].plainText(), "two x");
    EXPECT_EQ(blocks[4].level, 2);   // nested
    EXPECT_EQ(blocks[5].marker, "3.");
    EXPECT_EQ(blocks[6].marker, "4.");
    EXPECT_EQ(blocks[7].level, 0) << "a paragraph after the list";
    EXPECT_EQ(blocks[8].kind, MarkdownBlock::Code);
    EXPECT_EQ(blocks[8].code, "indented = code\n");
    EXPECT_EQ(blocks[9].info, "glsl");
    EXPECT_EQ(blocks[10].kind, MarkdownBlock::TableRow);
    EXPECT_TRUE(blocks[10].header);
    EXPECT_EQ(blocks[10].columns, 2);
    EXPECT_EQ(blocks[11].plainText(), "1\t2");
    EXPECT_FALSE(blocks[11].header);
    EXPECT_TRUE(blocks[12].quote);
    EXPECT_EQ(blocks.back().kind, MarkdownBlock::Rule);
}

TEST(MarkdownBlocks, APictureIsABlockOfItsOwnWithItsSourceAndAltText) {
    const auto blocks = parseMarkdownBlocks("![The *slab* test](pictures/slab.png)\n\nBefore ![a](b.png) after.\n");
    ASSERT_EQ(blocks.size(), 4u);
    EXPECT_EQ(blocks[0].kind, MarkdownBlock::Image) << "a picture alone takes its paragraph's place";
    EXPECT_EQ(blocks[0].source, "pictures/slab.png");
    EXPECT_EQ(blocks[0].plainText(), "The slab test");
    EXPECT_EQ(blocks[1].kind, MarkdownBlock::Paragraph);
    EXPECT_EQ(blocks[1].plainText(), "Before ");
    EXPECT_EQ(blocks[2].kind, MarkdownBlock::Image);
    EXPECT_EQ(blocks[2].source, "b.png");
    EXPECT_EQ(blocks[3].kind, MarkdownBlock::Paragraph);
    EXPECT_EQ(blocks[3].plainText(), " after.");
}

// A lesson's role markers are for the loader: the viewer shows a heading's words only.
TEST(MarkdownBlocks, HeadingsLoseTheirRoleMarker) {
    const auto blocks = parseMarkdownBlocks("## Stap 4: De renderer {#step .optional}\n\n## `fr` en *L* {#goals}\n\n"
                                            "## Braces {stay}\n\nText {#not-a-heading}\n");
    ASSERT_EQ(blocks.size(), 4u);
    EXPECT_EQ(blocks[0].plainText(), "Stap 4: De renderer");
    EXPECT_EQ(blocks[1].plainText(), "fr en L");
    ASSERT_EQ(blocks[1].spans.size(), 3u);
    EXPECT_EQ(blocks[1].spans[2].text, "L") << "an emptied last span goes";
    EXPECT_EQ(blocks[2].plainText(), "Braces {stay}");
    EXPECT_EQ(blocks[3].plainText(), "Text {#not-a-heading}");
}
