#!/usr/bin/python3
# Checks that every citation of a doc section (in comments, and in links between README.md and docs/*.md)
# names a section that exists; usage: check_doc_citations.py [REPO_ROOT]; exits 1 listing the dangling ones.
"""A citation belongs to the doc named last before it in the file (a doc's own bare § to itself):
  model.md §3, §4–5, §1, 2, 7, "model.md section 3": a heading numbered N ("## 3. Observables");
  a quoted name right after a doc or a §: a heading that holds it as whole words ("Holding R apart"
    names "### Holding R apart, eight times tighter"), after §N one in section N or a bold run-in
    label there (§9 "Substrate field" names "**Substrate field.** ...");
  model.md#anchor, [text](#anchor): the GitHub slug of a heading of the target file."""
import os
import re
import sys

SCANNED = ("apps", "bench", "cmake", "docs", "ensemble", "examples", "io", "kernels", "landscape",
           "python", "scripts", "tests", "README.md", "CMakeLists.txt")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*$")
LABEL = re.compile(r"^\s*(?:- )?\*\*([^*]+?)[.:]?\*\*")
DOC = re.compile(r"(?<![\w/.-])((?:[\w.-]+/)*[\w-]+\.md)(?:#([\w-]+))?")
SECTION = re.compile(r"(?:§|\bsection )\s*(\d+(?:\s*(?:[–-]|,|and)\s*\d+)*)")
LOCAL_LINK = re.compile(r"\]\(#([\w-]+)\)")
GAP = r"[ \t]*,?[ \t]*(?:and[ \t]+)?(?:\n[ \t]*(?://+|#+|\*)?[ \t]*)?"  # between a citation and the next part
QUOTE = re.compile(GAP + r'"(\w[^"]{0,79})"')


def slug(text):
    return re.sub(r"[^\w\- ]", "", text.strip().lower()).replace(" ", "-")


def parse_doc(path):
    """Headings (level, text, slug, line) and bold run-in labels (text, line) of a markdown file."""
    headings, labels, seen, fenced = [], [], {}, False
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and HEADING.match(line):
            level, text = HEADING.match(line).groups()
            base = slug(text)
            seen[base] = seen.get(base, -1) + 1
            headings.append((len(level), text, base + (f"-{seen[base]}" if seen[base] else ""), number))
        elif not fenced and LABEL.match(line):
            labels.append((LABEL.match(line).group(1), number))
    return headings, labels


def section_lines(headings, n):
    """The lines of the section numbered n ("## n. ..."), or None."""
    for i, (level, text, _, start) in enumerate(headings):
        if re.match(rf"{n}\.\s", text):
            return range(start, next((h[3] for h in headings[i + 1:] if h[0] <= level), 10**9))
    return None


def holds(text, quoted):
    quoted = re.sub(r"\s*\n\s*(?://+|#+|\*)?\s*", " ", quoted.strip()).lower()
    return re.search(r"(?<!\w)" + re.escape(quoted) + r"(?!\w)", text.lower()) is not None


def check_file(root, rel, docs):
    """The dangling citations of one file, as 'file:line: citation (why)'."""
    try:
        text = open(os.path.join(root, rel), encoding="utf-8").read()
    except (UnicodeDecodeError, OSError):
        return []
    is_doc, problems, current, end = rel in docs, [], None, -1

    def report(pos, what, why):
        problems.append(f"{rel}:{text.count(chr(10), 0, pos) + 1}: {what} ({why})")

    tokens = sorted([(m.start(), "doc", m) for m in DOC.finditer(text)] +
                    [(m.start(), "section", m) for m in SECTION.finditer(text)] +
                    [(m.start(), "local", m) for m in LOCAL_LINK.finditer(text) if is_doc],
                    key=lambda t: t[0])
    for pos, kind, m in tokens:
        where = None  # the lines of the cited numbered section
        if kind == "local":
            if m.group(1) not in [h[2] for h in docs[rel][0]]:
                report(pos, m.group(0), "no heading with this anchor")
            continue
        if kind == "doc":
            path = os.path.normpath(os.path.join(os.path.dirname(rel) if is_doc else "", m.group(1)))
            current = next((p for p in (path, "docs/" + os.path.basename(path)) if p in docs), None)
            if current is None and (path.startswith("docs/") or is_doc and m.group(2)):
                report(pos, m.group(0), "no such doc")
            elif current and m.group(2) and m.group(2) not in [h[2] for h in docs[current][0]]:
                report(pos, m.group(0), "no heading with this anchor")
        else:
            if is_doc and not re.fullmatch(GAP, text[end:pos]) and section_lines(docs[rel][0], 1):
                current = rel  # a bare § in a doc with numbered sections is one of its own
            if current is None:
                continue
            numbers = [int(n) for n in re.findall(r"\d+", m.group(1))]
            if re.search("[–-]", m.group(1)) and len(numbers) == 2:
                numbers = list(range(numbers[0], numbers[1] + 1))
            for n in numbers:
                if section_lines(docs[current][0], n) is None:
                    report(pos, f"{current} §{n}", "no section with this number")
            where = section_lines(docs[current][0], numbers[-1])
        end = m.end()
        while current and (q := QUOTE.match(text, end)):
            headings, labels = docs[current]
            names = [h[1] for h in headings if where is None or h[3] in where]
            names += [label for label, line in labels if where is not None and line in where]
            if not any(holds(name, q.group(1)) for name in names):
                report(q.start(1), f'{current} "{q.group(1)}"',
                       "no heading of that name" + (" in that section" if where else ""))
            end = q.end()
    return problems


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    paths = []
    for top in SCANNED:
        if os.path.isfile(os.path.join(root, top)):
            paths.append(top)
        for folder, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = [d for d in dirs if not d.startswith((".", "__"))]
            paths += [os.path.relpath(os.path.join(folder, f), root) for f in files]
    docs = {p: parse_doc(os.path.join(root, p)) for p in paths
            if p == "README.md" or p.startswith("docs/") and p.endswith(".md")}
    mine = os.path.relpath(os.path.abspath(__file__), os.path.abspath(root))
    problems = [p for rel in sorted(paths) if rel != mine for p in check_file(root, rel, docs)]
    print("\n".join(problems) if problems else f"doc citations: all resolve ({len(paths)} files checked)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
