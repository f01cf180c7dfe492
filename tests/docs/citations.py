#!/usr/bin/env python3
"""tests/docs/citations.py — no file cites a document the repository does not hold.

WHAT
  Walks every tracked text file of the repository (`git ls-files`; without git, the tree less
  its build folders) and checks:
    (a) every cited document is in the repository: an upper-case Markdown name with or
        without a path (README.md, BENCHMARKS.md, templates/README.md), any path under docs/
        ending in .md, and a bare README (the top-level README.md). A path is looked up
        beside the citing file, then from the repository's root;
    (b) every citation `<document> § <section>` (or `<document>'s § <section>`, the section
        free to run on to the next line) names a heading of that document, and in a Markdown
        file a bare `§ <section>` names one of the file's own headings. The rule: the cited
        words, cut at the first ( ) ] ; , : " | or sentence end and stripped of backticks, and
        a heading's text or its title (the text before a ':', ' (' or ' — '), likewise
        stripped, agree case-insensitively when one starts with the other at a word's end:
        "§ Temporal" names "Temporal accumulation", "§ GL runner says what each proves"
        names "GL runner", "§ Planted faults" names "Planted faults (`ctest -L mutants`)";
    (c) README.md has at most 400 lines;
    (d) every Markdown link `[text](path#anchor)` of a Markdown file reaches a file of the
        repository and, where it has an anchor, a heading GitHub gives that anchor; a
        citation `<document>.md#anchor` in any file (what ASCII-only files, the templates,
        write for a section) likewise.
  Each failure is a line "path:line: what", and the exit status is 1.

USAGE
  citations.py ROOT                 check the repository at ROOT
  citations.py ROOT --self-check    plant one fault of each kind, in memory, over ROOT's files,
                                    and require the check to name each where it was planted

WHY
  Comments, tests and documents cite each other by file and section ("docs/design.md
  § Ground truth"). A document that moves, a heading that is renamed or a file left outside
  the repository leaves citations a reader of a clone cannot follow; this finds them. The
  self-check keeps the check honest: a check that cannot fail proves nothing.
"""

import os
import re
import subprocess
import sys

README_MAX_LINES = 400

# A cited document: an upper-case Markdown name, with or without a path; a path under docs/;
# a bare README. A leading '/' (a path joined to a source directory in C++) is dropped.
DOC = (r"(?<![\w./-])/?(?:"
       r"(?:[\w.-]+/)*[A-Z][A-Z0-9_]*\.md"
       r"|docs/(?:[\w.-]+/)*[\w.-]+\.md"
       r"|README(?![\w.]))")
DOC_RE = re.compile(DOC + r"(?:#([\w-]+))?")
SECTION_RE = re.compile("(" + DOC + r")(?:'s)?\s*§\s*")
BARE_SECTION_RE = re.compile(r"(?<![\w.§])§\s+(?=[`A-Za-z])")
LINK_RE = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
URL_RE = re.compile(r"\b(?:https?|ftp|file)://\S+")
CUT_RE = re.compile(r"[()\];,:\"|]|\.(?:\s|$)")
HEADING_RE = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
FENCE_RE = re.compile(r"^\s*(```|~~~)")
SKIP_DIRS = {".git", "node_modules", "out"}


def list_files(root):
    """The repository's files, relative to root: git's list, else a walk of the tree."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True).stdout
        return [p for p in out.decode("utf-8", "surrogateescape").split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for d, dirs, names in os.walk(root):
            dirs[:] = [x for x in dirs if x not in SKIP_DIRS and not x.startswith("build")]
            files += [os.path.relpath(os.path.join(d, n), root) for n in names]
        return files


def read_text(root, path):
    """The file's text, or None when it is not UTF-8 text (images, binaries)."""
    try:
        with open(os.path.join(root, path), "rb") as f:
            data = f.read()
    except OSError:
        return None
    if b"\0" in data[:8192]:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


def plain(text):
    """A heading's or a citation's words: no inline markup, links as their text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)
    return text.replace("`", "").replace("*", "")


def normal(text):
    return " ".join(plain(text).lower().split())


def slug(text):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to '-'."""
    return re.sub(r"[^\w\- ]", "", plain(text).strip().lower()).replace(" ", "-")


def markdown_lines(text):
    """(line number, line, inside a fenced code block) for each line of a Markdown text."""
    fenced = False
    for n, line in enumerate(text.split("\n"), 1):
        if FENCE_RE.match(line):
            yield n, line, True
            fenced = not fenced
            continue
        yield n, line, fenced


class Document:
    def __init__(self, text):
        self.headings = []  # normalised heading texts, and each one's title alone
        self.anchors = set()
        seen = {}
        for _, line, fenced in markdown_lines(text):
            m = None if fenced else HEADING_RE.match(line)
            if not m:
                continue
            heading = normal(m.group(2))
            self.headings.append(heading)
            title = re.split(r":| \(| — ", heading, 1)[0].strip()
            if title and title != heading:
                self.headings.append(title)
            s = slug(m.group(2))
            n = seen.get(s, 0)
            seen[s] = n + 1
            self.anchors.add(s if n == 0 else f"{s}-{n}")

    def names(self, cited):
        """Whether a heading agrees with the cited words (the rule in WHAT, (b))."""
        def at_word_end(longer, shorter):
            return longer.startswith(shorter) and (len(longer) == len(shorter) or not longer[len(shorter)].isalnum())
        return bool(cited) and any(at_word_end(h, cited) or at_word_end(cited, h) for h in self.headings)


class Tree:
    """The repository's files and texts, read once for every check run over them."""

    def __init__(self, root):
        self.root = root
        self.paths = list_files(root)
        self.texts = {}
        self.docs = {}

    def text(self, path):
        if path not in self.texts:
            self.texts[path] = read_text(self.root, path)
        return self.texts[path]

    def document(self, path):
        if path not in self.docs:
            self.docs[path] = Document(self.text(path) or "")
        return self.docs[path]


class Checker:
    def __init__(self, tree, overlay=None):
        self.tree = tree
        self.root = tree.root
        self.overlay = overlay or {}
        self.paths = sorted(set(tree.paths) | set(self.overlay))
        self.present = set(self.paths)
        self.docs = {}
        self.errors = []

    def text(self, path):
        return self.overlay[path] if path in self.overlay else self.tree.text(path)

    def document(self, path):
        if path not in self.overlay:
            return self.tree.document(path)
        if path not in self.docs:
            self.docs[path] = Document(self.overlay[path])
        return self.docs[path]

    def fail(self, path, line, what):
        error = f"{path}:{line}: {what}"
        if error not in self.errors:  # a link's target is also a cited document: say it once
            self.errors.append(error)

    def resolve(self, citing, cited):
        """The repository path a citation in `citing` names, or None when it holds none."""
        cited = cited.lstrip("/")
        if cited == "README":
            cited = "README.md"
        for candidate in (os.path.normpath(os.path.join(os.path.dirname(citing), cited)), os.path.normpath(cited)):
            if candidate in self.present:
                return candidate
        return None

    def check_section(self, path, n, target, cited_doc, words):
        words = CUT_RE.split(words, 1)[0]
        cited = normal(words)
        if not self.document(target).names(cited):
            self.fail(path, n, f"cites {cited_doc} § {words.strip()}, which is no heading of {target}")

    def check_anchor(self, path, n, target, anchor, shown):
        if anchor and target.endswith(".md") and anchor not in self.document(target).anchors:
            self.fail(path, n, f"links {shown}: {target} has no heading with the anchor #{anchor}")

    def check_file(self, path):
        text = self.text(path)
        if text is None:
            return
        markdown = path.endswith(".md")
        lines = text.split("\n")
        fences = [f for _, _, f in markdown_lines(text)] if markdown else [False] * len(lines)
        for i, raw in enumerate(lines):
            n = i + 1
            if "md" not in raw and "README" not in raw and "§" not in raw and "](" not in raw:
                continue
            line = URL_RE.sub(" ", raw)
            following = lines[i + 1] if i + 1 < len(lines) else ""
            following = re.sub(r"^\s*(?://+|#+|\*+|--|<!--)?\s*", "", URL_RE.sub(" ", following))
            joined = line + " " + following
            # (a) and (d): documents named, with or without an anchor.
            for m in DOC_RE.finditer(line):
                target = self.resolve(path, m.group(0).split("#")[0])
                if target is None:
                    self.fail(path, n, f"cites {m.group(0)}, which the repository does not hold")
                else:
                    self.check_anchor(path, n, target, m.group(1), m.group(0))
            # (b): <document> § <section>, the section possibly on the next line.
            for m in SECTION_RE.finditer(joined):
                if m.start() >= len(line):
                    break
                target = self.resolve(path, m.group(1))
                if target is not None and target.endswith(".md"):
                    self.check_section(path, n, target, m.group(1), joined[m.end():])
            if markdown and not fences[i]:
                cited_spans = [(m.start(), m.end()) for m in SECTION_RE.finditer(joined)]
                for m in BARE_SECTION_RE.finditer(line):
                    if any(a <= m.start() < b for a, b in cited_spans):
                        continue
                    self.check_section(path, n, path, path, joined[m.end():])
                # (d): Markdown links, outside inline code.
                for m in LINK_RE.finditer(re.sub(r"`[^`]*`", lambda c: " " * len(c.group(0)), raw)):
                    href = m.group(1)
                    if re.match(r"^[a-z][a-z0-9+.-]*:", href):
                        continue
                    file_part, _, anchor = href.partition("#")
                    target = path if not file_part else self.resolve(path, file_part)
                    if target is None and file_part and os.path.isdir(os.path.join(self.root, os.path.dirname(path), file_part)):
                        continue  # a folder
                    if target is None:
                        self.fail(path, n, f"links {href}, which the repository does not hold")
                    else:
                        self.check_anchor(path, n, target, anchor, href)

    def run(self):
        for path in self.paths:
            self.check_file(path)
        readme = self.text("README.md")
        if readme is None:
            self.fail("README.md", 1, "the repository has no README.md")
        else:
            count = readme.count("\n") + (0 if readme.endswith("\n") or not readme else 1)
            if count > README_MAX_LINES:
                self.fail("README.md", count, f"README.md has {count} lines (at most {README_MAX_LINES}: move references to docs/)")
        return self.errors


def planted_faults(tree):
    """(name, overlay, where the check must report it): one fault of each kind."""
    base = Checker(tree)
    readme = base.text("README.md") or ""
    cli = base.text("docs/cli.md") or ""
    cli_links = cli.count("\n") + 1
    absent_doc = "docs/" + "absent.md"
    design = "DESIGN" + ".md"
    ours = "docs/design" + ".md"  # written apart, so this file does not cite what it plants
    return [
        ("a document the repository does not hold",
         {"planted/missing.cpp": f"// the closed forms ({design})\n"}, "planted/missing.cpp:1"),
        ("a path under docs/ that does not exist",
         {"planted/missing.hpp": f"// see {absent_doc}\n"}, "planted/missing.hpp:1"),
        ("a section that is no heading",
         {"planted/section.hpp": f"// {ours} § No such section\n"}, "planted/section.hpp:1"),
        ("a section on the next line that is no heading",
         {"planted/section.cpp": f"// as {ours}\n// § Nor this one says\n"}, "planted/section.cpp:1"),
        ("a bare section in a Markdown file that is none of its headings",
         {"docs/cli.md": cli + "\nSee § Nothing of the kind.\n"}, f"docs/cli.md:{cli_links + 1}"),
        ("a README over 400 lines",
         {"README.md": readme + "\n" * (README_MAX_LINES + 1)}, "README.md:"),
        ("a link to a heading that does not exist",
         {"docs/cli.md": cli + "\n[the design](design.md#no-such-heading)\n"}, f"docs/cli.md:{cli_links + 1}"),
        ("a link to a file that does not exist",
         {"docs/cli.md": cli + f"\n[nowhere]({absent_doc.split('/')[1]})\n"}, f"docs/cli.md:{cli_links + 1}"),
        ("an anchor citation in an ASCII file that names no heading",
         {"planted/planted.glsl": f"// aogen's AO ({ours}#no-such-anchor)\n"}, "planted/planted.glsl:1"),
    ]


def self_check(root):
    """Every planted fault must be reported where it was planted."""
    survived = []
    tree = Tree(root)
    for name, overlay, where in planted_faults(tree):
        errors = Checker(tree, overlay).run()
        caught = [e for e in errors if e.startswith(where)]
        print(f"{'caught' if caught else 'SURVIVED'}: {name}" + (f" ({caught[0]})" if caught else f" (nothing at {where})"))
        if not caught:
            survived.append(name)
    if survived:
        print(f"{len(survived)} planted fault(s) not caught: the check cannot fail where it must")
        return 1
    return 0


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--self-check"):
        print("usage: citations.py ROOT [--self-check]", file=sys.stderr)
        return 2
    root = os.path.abspath(argv[1])
    if len(argv) == 3:
        return self_check(root)
    errors = Checker(Tree(root)).run()
    for e in errors:
        print(e)
    if errors:
        print(f"{len(errors)} citation(s) the repository cannot follow")
        return 1
    print("every cited document and section is in the repository; README.md is within "
          f"{README_MAX_LINES} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
