"""raylab-lesson export: every lesson's two handouts are well-formed HTML (each tag closed, in
order) with every picture inside the page as a decodable PNG."""
import base64
import glob
import html.parser
import os
import subprocess
import tempfile
import unittest

ROOT = os.environ.get("RAYLAB_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
LESSON = os.path.join(os.environ.get("RAYLAB_BUILD_DIR", os.path.join(ROOT, "build")), "raylab-lesson")
VOID = {"br", "hr", "img", "meta", "link", "input", "wbr", "col", "area", "base", "source"}
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Balance(html.parser.HTMLParser):
    """Checks that every element is closed in order; collects the pictures' sources."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.errors, self.images, self.doctype = [], [], [], False

    def handle_decl(self, decl):
        self.doctype = self.doctype or decl.lower() == "doctype html"

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.images.append(dict(attrs).get("src", ""))
        if tag not in VOID:
            self.stack.append((tag, self.getpos()))

    def handle_endtag(self, tag):
        if tag in VOID:
            self.errors.append(f"{self.getpos()}: </{tag}> closes a void element")
        elif not self.stack or self.stack[-1][0] != tag:
            self.errors.append(f"{self.getpos()}: </{tag}> closes {self.stack[-1] if self.stack else 'nothing'}")
        else:
            self.stack.pop()


def balanced(text):
    parser = Balance()
    parser.feed(text)
    parser.close()
    parser.errors += [f"{pos}: <{tag}> never closed" for tag, pos in parser.stack]
    return parser


class LessonSheets(unittest.TestCase):
    def test_the_checker_can_fail(self):
        self.assertTrue(balanced("<p><em>a</p></em>").errors)
        self.assertTrue(balanced("<ul><li>a</ul>").errors)
        self.assertFalse(balanced("<!DOCTYPE html><p>a<br><img src=x></p>").errors)

    def test_every_lesson_exports_well_formed_sheets_with_embedded_pictures(self):
        lessons = sorted(f for f in glob.glob(os.path.join(ROOT, "lessons", "*.md")) if not f.endswith("README.md"))
        self.assertGreaterEqual(len(lessons), 12)
        with tempfile.TemporaryDirectory() as tmp:
            for lesson in lessons:
                for sheet in ("--pupil", "--teacher"):
                    with self.subTest(lesson=os.path.basename(lesson), sheet=sheet):
                        out = os.path.join(tmp, "sheet.html")
                        done = subprocess.run([LESSON, "export", lesson, sheet, "-o", out], capture_output=True, text=True, timeout=120)
                        self.assertEqual(done.returncode, 0, done.stderr)
                        with open(out, encoding="utf-8") as f:
                            page = balanced(f.read())
                        self.assertTrue(page.doctype)
                        self.assertEqual(page.errors, [])
                        self.assertTrue(page.images, "every lesson has a picture")
                        for src in page.images:
                            self.assertTrue(src.startswith("data:image/png;base64,"), src[:60])
                            self.assertEqual(base64.b64decode(src.split(",", 1)[1], validate=True)[:8], PNG_SIGNATURE)


if __name__ == "__main__":
    unittest.main()
