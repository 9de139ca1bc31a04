"""Every relative link of the pages (README.md, docs/**/*.md, campaigns/**/*.md) resolves: each
[text](path) and ![alt](path), each reference definition [label]: path and each <img src="path">
names a file or folder of the repository (relative to the page; a leading / from the repository's
root). URLs (http, https, ftp, mailto) are skipped. An anchor (path#anchor, or #anchor on the same
page) is checked too: against the headings of the Markdown page it points into, as GitHub makes
them (lower case, punctuation dropped, spaces to hyphens, -1, -2 … on repeats); an anchor into
another kind of file is not read. Code (fenced blocks and `spans`) is not a link and is skipped.
The check finds a missing file, a link out of the repository and a wrong anchor."""
import os
import pathlib
import re
import tempfile
import unittest
import urllib.parse

ROOT = pathlib.Path(__file__).resolve().parents[2]
URL = re.compile(r"^(?:https?|ftp|mailto):", re.I)
FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1")
# [text](target "title") and ![alt](target): the text may hold one level of brackets
INLINE = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(<[^>]*>|[^\s()]*(?:\([^\s()]*\)[^\s()]*)*)"
                    r"(?:\s+(?:\"[^\"]*\"|'[^']*'|\([^)]*\)))?\s*\)")
REFERENCE = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)")
IMG = re.compile(r"<img\b[^>]*\bsrc\s*=\s*[\"']([^\"']+)[\"']", re.I)
HEADING = re.compile(r"^ {0,3}#{1,6}\s+(.*?)\s*#*\s*$")


def pages(root=ROOT):
    """The pages whose links are checked: README.md, docs/**/*.md and campaigns/**/*.md."""
    out = [root / "README.md"] if (root / "README.md").exists() else []
    for top in ("docs", "campaigns"):
        out += sorted((root / top).rglob("*.md"))
    return out


def _prose_lines(text):
    """(line number, line) of the text outside fenced code blocks, code spans blanked."""
    fence = None
    for n, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if fence:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) and not line.strip()[len(m.group(1)):]:
                fence = None
            continue
        if m:
            fence = m.group(1)
            continue
        yield n, SPAN.sub(lambda s: " " * len(s.group(0)), line)


def links(text):
    """(line number, target) of every link of a Markdown text (code skipped)."""
    out = []
    for n, line in _prose_lines(text):
        for rx in (INLINE, REFERENCE, IMG):
            out += [(n, m.group(1).strip("<>")) for m in rx.finditer(line)]
    return out


def slug(heading):
    """GitHub's anchor of a heading: markup dropped, lower case, every character but letters,
    digits, _, - and spaces dropped, spaces to hyphens."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text stays
    return re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")


def anchors(text):
    """The anchors GitHub gives the headings of a Markdown text (repeats numbered -1, -2, ...)."""
    seen, out = {}, set()
    for _, line in _prose_lines(text):
        m = HEADING.match(line)
        if not m:
            continue
        s = slug(m.group(1))
        k = seen.get(s, 0)
        seen[s] = k + 1
        out.add(s if k == 0 else f"{s}-{k}")
    return out


def broken(page, root=ROOT):
    """The broken links of one page: ['page:line: target (why)', ...]."""
    text = page.read_text(encoding="utf-8")
    out = []
    for n, target in links(text):
        if not target or URL.match(target):
            continue
        path, _, anchor = target.partition("#")
        path = urllib.parse.unquote(path.split("?")[0])
        where = f"{page.relative_to(root)}:{n}: {target}"
        if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", path):
            out.append(f"{where} (a scheme that is not checked: write a path or an http(s) URL)")
            continue
        dest = (root / path.lstrip("/")) if path.startswith("/") else (page.parent / path if path else page)
        dest = pathlib.Path(os.path.normpath(dest))
        if root != dest and root not in dest.parents:
            out.append(f"{where} (outside the repository)")
        elif not dest.exists():
            out.append(f"{where} (no such file: {dest.relative_to(root)})")
        elif anchor and dest.suffix.lower() == ".md" and dest.is_file():
            if urllib.parse.unquote(anchor).lower() not in anchors(dest.read_text(encoding="utf-8")):
                out.append(f"{where} (no heading #{anchor} in {dest.relative_to(root)})")
    return out


class Links(unittest.TestCase):
    def test_every_relative_link_resolves(self):
        found = pages()
        self.assertGreater(len(found), 20, "the pages were not found")
        self.assertGreater(sum(len(links(p.read_text(encoding="utf-8"))) for p in found), 20)
        self.assertEqual([b for p in found for b in broken(p)], [])

    def test_the_check_can_fail(self):
        with tempfile.TemporaryDirectory() as d:
            root = pathlib.Path(d).resolve()
            (root / "docs" / "pictures").mkdir(parents=True)
            (root / "docs" / "pictures" / "a.png").write_bytes(b"png")
            (root / "README.md").write_text("# The project\n\n## Figs. 16–19: the tablet\n", encoding="utf-8")
            page = root / "docs" / "page.md"
            page.write_text("\n".join([
                "# A page", "",
                "![a](pictures/a.png) [up](../README.md#figs-1619-the-tablet) [root](/docs/pictures/a.png)",
                "[here](#a-page) [site](https://example.org/x.md) [mail](mailto:someone@example.org)",
                "[ref]: pictures/a.png", "`[code](nowhere.md)`", "```", "[fenced](nowhere.md)", "```",
                "![b](pictures/b.png) [gone](../docs/missing.md) [out](../../elsewhere.md)",
                "[anchor](../README.md#no-such-heading) [self](#nowhere) <img src=\"pictures/c.png\">",
                "[ref2]: missing/file.csv"]) + "\n", encoding="utf-8")
            self.assertEqual(pages(root), [root / "README.md", page])
            self.assertEqual([b.split(": ", 1)[1].split(" (")[0] for b in broken(page, root)],
                             ["pictures/b.png", "../docs/missing.md", "../../elsewhere.md",
                              "../README.md#no-such-heading", "#nowhere", "pictures/c.png", "missing/file.csv"])

    def test_headings_become_githubs_anchors(self):
        self.assertEqual(slug("E4: the same tests without flat walls (`profile/*-grips1|2/`)"),
                         "e4-the-same-tests-without-flat-walls-profile-grips12")
        self.assertEqual(anchors("# A\n## A\n```\n# not a heading\n```\n## Décision: ◐\n"),
                         {"a", "a-1", "décision-"})


if __name__ == "__main__":
    unittest.main()
