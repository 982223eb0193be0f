#!/usr/bin/env python3
"""Every citation of a lemma names one that exists.

Code, tests and docs cite proofs as `proofs/<file>.md#<anchor>` (proofs/README.md). Each such
anchor must be an explicit `<a id="...">` in that file or the GitHub anchor of one of its
headings; a citation of a missing file or anchor is listed and the test fails.

Usage: proof_citations.py SOURCE_DIR
"""
import os
import re
import sys

CITATION = re.compile(r"proofs/([\w-]+\.md)#([\w-]+)")
SCANNED = ("src", "include", "tests", "docs", "proofs", "python", "scripts", "fuzz")


def heading_anchor(title):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    title = re.sub(r"<a id=\"[^\"]*\"></a>", "", title).strip().lower()
    return re.sub(r"[^\w\- ]", "", title).replace(" ", "-")


def anchors_of(path):
    with open(path, encoding="utf-8") as text:
        content = text.read()
    found = set(re.findall(r'<a id="([^"]+)"', content))
    found |= {heading_anchor(h) for h in re.findall(r"^#+ (.*)$", content, re.M)}
    return found


def main(root):
    proofs = os.path.join(root, "proofs")
    anchors = {name: anchors_of(os.path.join(proofs, name))
               for name in os.listdir(proofs) if name.endswith(".md")}
    missing = []
    checked = 0
    for top in SCANNED:
        for directory, _, names in os.walk(os.path.join(root, top)):
            for name in names:
                path = os.path.join(directory, name)
                try:
                    with open(path, encoding="utf-8") as text:
                        content = text.read()
                except (UnicodeDecodeError, OSError):
                    continue
                for match in CITATION.finditer(content):
                    file, anchor = match.groups()
                    checked += 1
                    if anchor not in anchors.get(file, set()):
                        missing.append(f"{os.path.relpath(path, root)}: proofs/{file}#{anchor}")
    for line in sorted(set(missing)):
        print(line)
    print(f"{checked} citations checked, {len(set(missing))} of missing lemmas")
    return 1 if missing or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
