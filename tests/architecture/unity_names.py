#!/usr/bin/env python3
"""Names with internal linkage that two files of one unity-built target both define.

Every stage, the CLI and the test and benchmark binaries compile in unity batches of 8 files
(docs/reliability.md#ci-time). A batch is one translation unit, so a helper that two files each
define in an anonymous namespace (or as a file-`static`) clashes as soon as both land in the
same batch, and adding any file moves every later batch boundary. This scan finds such names
before a batch boundary does: run with the source root (default: this checkout); prints each
clash as `target: name: file, file` and exits 1 when there is one that --baseline does not
list (or when the baseline lists one that is gone).

The scan reads declarations, not C++: comments and literals are blanked, braces are tracked,
and the name of each declaration directly inside an anonymous namespace (or `static` at
namespace scope) is taken from its head (text up to its first `{`, `;` or `=`). Overloads in
different files count as clashes too: they compile only while their parameter types differ.
"""

import argparse
import collections
import pathlib
import re
import sys

IDENTIFIER = re.compile(r"[A-Za-z_]\w*")
KEYWORDS = {
    "const", "constexpr", "static", "inline", "auto", "void", "int", "double", "bool", "char",
    "unsigned", "long", "short", "float", "signed", "struct", "class", "enum", "union", "using",
    "template", "typename", "operator", "return", "thread_local", "volatile", "noexcept",
    "override", "final", "std", "size_t", "extern", "friend", "typedef", "namespace", "if",
    "for", "while", "switch", "do", "else", "new", "delete", "sizeof", "decltype",
}


def blank_comments_and_literals(text: str) -> str:
    """Comments, string and character literals (raw strings too) become spaces; newlines stay."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i + 2)
            delimiter = text[i + 2:open_paren]
            close = text.find(")" + delimiter + '"', open_paren)
            j = n if close < 0 else close + len(delimiter) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator: 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "#" and (i == 0 or text[i - 1] == "\n"):  # a preprocessor line (with continuations)
            j = i
            while True:
                j = text.find("\n", j)
                if j < 0 or text[j - 1] != "\\":
                    break
                j += 1
            j = n if j < 0 else j
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def strip_template_heads(head: str) -> str:
    """`template <...>` prefixes removed (angle brackets balanced)."""
    while True:
        m = re.match(r"\s*template\s*<", head)
        if not m:
            return head
        depth, i = 1, m.end()
        while i < len(head) and depth:
            depth += {"<": 1, ">": -1}.get(head[i], 0)
            i += 1
        head = head[i:]


def declared_name(head: str):
    """The name a declaration head introduces, or None (a `using namespace`, an assertion...)."""
    head = strip_template_heads(head).strip()
    if not head or head.startswith(("using namespace", "static_assert", "namespace", "extern \"")):
        return None
    m = re.match(r"(?:struct|class|union|enum(?:\s+class)?)\s+([A-Za-z_]\w*)", head)
    if m:
        return m.group(1)
    m = re.match(r"using\s+([A-Za-z_]\w*)\s*=", head)
    if m:
        return m.group(1)
    if head.startswith("using"):  # a using-declaration names an entity declared elsewhere
        return None
    if re.match(r"[A-Z][A-Z0-9_]*\s*\(", head):  # a macro: TEST(...), TEST_F(...)
        return None
    # A variable's name stands before its initializer; a function's before its parameters.
    equals = head.find("=")
    paren = head.find("(")
    cut = equals if equals >= 0 and (paren < 0 or equals < paren) else paren
    before = head if cut < 0 else head[:cut]
    before = re.sub(r"\[[^\]]*\]\s*$", "", before.rstrip())  # an array's bound
    if re.search(r"\boperator\b", before):
        return None
    names = [w for w in IDENTIFIER.findall(before) if w not in KEYWORDS]
    return names[-1] if names else None


Declaration = collections.namedtuple("Declaration", "name line scope alias")


def internal_names(text: str):
    """A Declaration for each name with internal linkage at namespace scope."""
    text = blank_comments_and_literals(text)
    names = []
    stack = []  # one entry per open brace: "anon", "namespace" or "block"
    head_start = 0
    paren = 0

    def at_namespace_scope():
        return all(kind != "block" for kind, _ in stack)

    def take(end):
        head = text[head_start:end]
        if not at_namespace_scope() or not head.strip():
            return
        anonymous = any(kind == "anon" for kind, _ in stack)
        is_static = re.match(r"\s*(?:template\s*<[^{;]*>\s*)?static\b", head) is not None
        if not (anonymous or is_static):
            return
        name = declared_name(head)
        if name:
            line = text.count("\n", 0, head_start + len(head) - len(head.lstrip())) + 1
            scope = "::".join(named for kind, named in stack if kind == "namespace")
            # An alias compared without qualifiers: `std::vector<Eigen::Vector3d>` and
            # `std::vector<Vector3d>` are the same text (a wrong "same" still fails to compile).
            alias = re.sub(r"\w+::|\s+", "", head.split("=", 1)[1]) if re.match(r"\s*using\s", head) else None
            names.append(Declaration(name, line, scope, alias))

    i = 0
    while i < len(text):
        c = text[i]
        if c == "(":
            paren += 1
        elif c == ")":
            paren -= 1
        elif paren == 0 and c == "{":
            head = text[head_start:i]
            named = re.search(r"(?:^|[\s;}])namespace\s+([\w:]+)\s*$", head)
            if re.search(r"(?:^|[\s;}])namespace\s*$", head):
                stack.append(("anon", ""))
                head_start = i + 1
            elif named:
                stack.append(("namespace", named.group(1)))
                head_start = i + 1
            elif re.search(r'extern\s+"C"\s*$', head):
                stack.append(("extern", ""))
                head_start = i + 1
            else:
                take(i)
                stack.append(("block", ""))
                # Skip to the matching brace: the body declares nothing at namespace scope.
                depth = 1
                i += 1
                while i < len(text) and depth:
                    depth += {"{": 1, "}": -1}.get(text[i], 0)
                    i += 1
                stack.pop()
                # `struct X {...} x;` or `T t{...};`: the rest of the statement is not a new head.
                rest = re.match(r"[^;{}]*;", text[i:])
                if rest and not re.search(r"\w\s*\(", rest.group(0)):
                    i += rest.end()
                head_start = i
                continue
        elif paren == 0 and c == ";":
            take(i)
            head_start = i + 1
        elif paren == 0 and c == "}":
            if stack:
                stack.pop()
            head_start = i + 1
        i += 1
    return names


def unity_targets(root: pathlib.Path):
    """Each unity-built target's sources, as the CMake files glob them."""
    src = root / "src"
    for stage in sorted(p for p in src.iterdir() if p.is_dir()):
        if stage.name in ("exact", "app"):  # exact is not a unity build; app is below
            continue
        yield f"grpvss_{stage.name}", sorted(stage.glob("*.cpp"))
    yield "grpvss", sorted((src / "app").glob("*.cpp"))
    yield "grpvss_interactive", sorted((src / "app" / "interactive").glob("*.cpp"))
    tests = root / "tests"
    test_sources = [p for p in tests.glob("*/*_test.cpp") if p.parent.name != "bench"]
    test_sources += [p for p in tests.glob("*/**/*_test.cpp") if "bench" not in p.parts and p not in test_sources]
    yield "grpvss_tests", sorted(set(test_sources) | set((tests / "support").glob("*.cpp")))
    yield "grpvss_bench", sorted(list((tests / "bench").glob("*.cpp")) +
                                 [tests / "bench" / "robots" / "bench_cells.cpp",
                                  tests / "support" / "industrial_robots.cpp"])


def clashes(root: pathlib.Path):
    for target, sources in unity_targets(root):
        where = collections.defaultdict(list)  # (scope, name) -> [(place, alias)]
        for path in sources:
            seen = set()
            for d in internal_names(path.read_text(encoding="utf-8")):
                if (d.scope, d.name) not in seen:
                    seen.add((d.scope, d.name))
                    where[(d.scope, d.name)].append((f"{path.relative_to(root)}:{d.line}", d.alias))
        for (scope, name), places in sorted(where.items()):
            aliases = {alias for _, alias in places}
            # The same alias declared twice names the same type: legal in one translation unit.
            if len(places) > 1 and not (len(aliases) == 1 and None not in aliases):
                yield target, f"{scope}::{name}" if scope else name, [place for place, _ in places]


def read_baseline(path: pathlib.Path):
    """`target: name` lines (# comments, blank lines ignored): clashes known when the scan began."""
    accepted = set()
    for line in path.read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            accepted.add(line)
    return accepted


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?", default=pathlib.Path(__file__).resolve().parents[2],
                        type=pathlib.Path, help="the source root (default: this checkout)")
    parser.add_argument("--baseline", type=pathlib.Path,
                        help="clashes accepted for now (`target: name` per line); one that is gone "
                             "must be removed from it")
    args = parser.parse_args()
    accepted = read_baseline(args.baseline) if args.baseline else set()
    found = list(clashes(args.root))
    new = [(t, n, p) for t, n, p in found if f"{t}: {n}" not in accepted]
    gone = sorted(accepted - {f"{t}: {n}" for t, n, _ in found})
    for target, name, places in new:
        print(f"{target}: {name}: {', '.join(places)}")
    for entry in gone:
        print(f"{args.baseline}: {entry}: no longer clashes; remove it from the baseline")
    if new:
        print(f"{len(new)} name(s) defined with internal linkage in two files of one unity target: "
              "rename one, or define it once in a shared header (docs/reliability.md#ci-time)",
              file=sys.stderr)
    return 1 if new or gone else 0


if __name__ == "__main__":
    sys.exit(main())
