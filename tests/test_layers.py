"""The house rules of docs/design.md's map, checked on the source: one gateway to
the compiled core, limits read from it, the engine below the public API, small modules
and functions, no import circle."""

from __future__ import annotations

import ast
import re
from pathlib import Path

PKG = Path(__file__).resolve().parents[1] / "src" / "minkowski2d"

#: Modules not yet moved onto the rules (each named, with the reason, in the design note).
NOT_YET: set[str] = set()
MAX_MODULE_LINES = 900
MAX_FUNCTION_LINES = 120


def _modules():
    for p in sorted(PKG.rglob("*.py")):
        yield p.relative_to(PKG).as_posix(), p


def _code(text: str) -> str:
    """The text without docstrings, comments and string literals (what the code writes)."""
    tree = ast.parse(text)
    lines = text.splitlines()
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            for k in range(node.lineno - 1, node.end_lineno):
                lines[k] = ""
    return "\n".join(re.sub(r"#.*", "", line) for line in lines)


def test_one_gateway_to_the_compiled_core():
    importers = [
        name
        for name, p in _modules()
        if re.search(r"import _ext\b|_core\._ext import|_core import _ext", _code(p.read_text()))
    ]
    assert set(importers) - NOT_YET == {"_engine/core.py"}, importers


def test_no_module_writes_the_core_limits():
    pattern = re.compile(r"1\s*<<\s*(53|62)\b|2\s*\*\*\s*(53|62)\b")
    bad = [name for name, p in _modules() if pattern.search(_code(p.read_text()))]
    assert set(bad) - NOT_YET == set(), bad


def test_the_engine_imports_no_public_module():
    public = re.compile(
        r"from \.\.(convex|batch|collision|general|nesting|offset|planning|trace|predicates"
        r"|io|cli|plot|animation)\b"
    )
    bad = [
        name
        for name, p in _modules()
        if name.startswith("_engine/") and public.search(_code(p.read_text()))
    ]
    assert not bad, bad


STATUS_NAMES = {"st", "status", "code"}


def test_no_status_code_is_an_integer_literal():
    # a core status is compared with its name (core.Status.OK, core.PLAN_NO_PATH, ...),
    # never with a number typed by hand
    bad = []
    for name, p in _modules():
        for node in ast.walk(ast.parse(p.read_text())):
            if not isinstance(node, ast.Compare):
                continue
            sides = [node.left, *node.comparators]
            names = [s.value if isinstance(s, ast.Subscript) else s for s in sides]
            if not any(isinstance(n, ast.Name) and n.id in STATUS_NAMES for n in names):
                continue
            lits = [
                s
                for s in sides
                if (isinstance(s, ast.Constant) and type(s.value) is int)
                or (isinstance(s, ast.UnaryOp) and isinstance(s.operand, ast.Constant))
            ]
            if lits:
                bad.append(f"{name}:{node.lineno}")
    assert not bad, bad


def _strings(text: str) -> list[str]:
    """The string literals of the code (f-string parts included), docstrings left out."""
    tree = ast.parse(text)
    docs = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                docs.add(id(body[0].value))
    return [
        n.value
        for n in ast.walk(tree)
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docs
    ]


#: tables keyed by codes that are not the core's: GEOS's geometry type ids (shapely's
#: numbering), the GeoJSON nesting depth of each geometry type
NOT_CORE_CODES = {"_engine/containers.py", "io/read.py"}


def _is_int(node: ast.AST) -> bool:
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        node = node.operand
    return isinstance(node, ast.Constant) and type(node.value) is int


def test_no_code_table_outside_the_core():
    # a table of names and numbers typed by hand ({"round": 0, ...} or {0: "flat", ...})
    # restates a code of the core: read the core's names (core.OVERLAY_OPS, ...) instead
    bad = []
    for name, p in _modules():
        if name in NOT_CORE_CODES:
            continue
        for node in ast.walk(ast.parse(p.read_text())):
            if not isinstance(node, ast.Dict) or len(node.keys) < 2 or None in node.keys:
                continue
            strs = [isinstance(x, ast.Constant) and isinstance(x.value, str) for x in node.keys]
            ints = [_is_int(x) for x in node.keys]
            vstrs = [isinstance(v, ast.Constant) and isinstance(v.value, str) for v in node.values]
            vints = [_is_int(v) for v in node.values]
            if (all(strs) and all(vints)) or (all(ints) and all(vstrs)):
                bad.append(f"{name}:{node.lineno}")
    assert not bad, bad


#: each fault's message, written once: the words and the one module that writes them
ONE_MESSAGE = {
    "non-finite coordinate": "_engine/status.py",
    "GeometryCollection holding": "_engine/polygon.py",
    "overflows float64 (a coordinate": "_engine/status.py",
    "needs more work than": "_engine/status.py",
}


def test_each_fault_has_one_message():
    homes: dict[str, set[str]] = {words: set() for words in ONE_MESSAGE}
    for name, p in _modules():
        if name.startswith("io/"):  # file formats: a bad file is an InputFormatError
            continue
        for text in _strings(p.read_text()):
            for words in ONE_MESSAGE:
                if words in text:
                    homes[words].add(name)
    assert homes == {w: {m} for w, m in ONE_MESSAGE.items()}, homes


#: the reading primitives (the dtype policy's, the shapely readings, the core's list pass):
#: every polygon is read through the one reader, _engine/reader.read; only it (and the
#: modules that define them) call these
READING = {"as_array", "py_points", "polygon_parts", "flatten", "_shapely_coords"}
READER_HOMES = {"_engine/reader.py", "_engine/coerce.py", "_engine/polygon.py", "_engine/core.py"}


def _called_names(tree: ast.AST) -> set[tuple[str, int]]:
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            f = node.func
            fname = (
                f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""
            )
            out.add((fname, node.lineno))
        elif isinstance(node, ast.ImportFrom):
            out.update((a.name, node.lineno) for a in node.names)
    return out


def test_one_polygon_reader():
    bad = []
    for name, p in _modules():
        if name in READER_HOMES:
            continue
        for fname, line in _called_names(ast.parse(p.read_text())):
            if fname in READING:
                bad.append(f"{name}:{line} {fname}")
    assert not bad, sorted(bad)


def test_the_reader_check_finds_calls():
    found = _called_names(ast.parse("from x import as_array\nD.flatten(a)\npy_points(b)"))
    assert {n for n, _ in found} == {"as_array", "flatten", "py_points"}


def test_modules_and_functions_are_small():
    big = []
    for name, p in _modules():
        text = p.read_text()
        if name not in NOT_YET and len(text.splitlines()) > MAX_MODULE_LINES:
            big.append((name, len(text.splitlines())))
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1
                if n > MAX_FUNCTION_LINES and name not in NOT_YET:
                    big.append((f"{name}:{node.name}", n))
    assert not big, big


CORE = PKG / "_core"
#: Core files not yet moved onto the size rule (none: every file of _core keeps it)
CPP_NOT_YET: set[str] = set()


def _cpp_blank(text: str) -> str:
    """The C++ text with comments, string and character literals and preprocessor lines
    blanked (newlines kept, so line numbers stay)."""
    out = list(text)
    i, n = 0, len(text)

    def blank(a: int, b: int) -> None:
        for k in range(a, b):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if text.startswith("//", i) or (
            c == "#" and text[text.rfind("\n", 0, i) + 1 : i].strip() == ""
        ):
            j = text.find("\n", i)
            j = n if j < 0 else j
            blank(i, j)
            i = j
        elif text.startswith("/*", i):
            j = text.index("*/", i + 2) + 2
            blank(i, j)
            i = j
        elif c == '"' or (c == "'" and not text[i - 1].isalnum()):
            j = i + 1
            while text[j] != c:
                j += 2 if text[j] == "\\" else 1
            blank(i + 1, j)
            i = j + 1
        else:
            i += 1
    return "".join(out)


_SIGNATURE_END = re.compile(r"\)\s*(const|noexcept|override|final|mutable|->[^;{}]*|\s)*$")


def _cpp_functions(text: str):
    """(name, lines) of every function defined at namespace or class scope: the lines from
    its opening brace to its closing one (lambdas and local classes inside count toward
    it). A brace-matching scan: a '{' at namespace/class scope opens a function when the
    code before it ends with ')' (and qualifiers), a scope after namespace/struct/class/
    union, anything else (an enum, an initializer) a block that is skipped."""
    code = _cpp_blank(text)
    stack: list[tuple[str, int, str]] = []  # (kind, line of the brace, name)
    line, last = 1, 0
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            head = " ".join(code[last:i].split())
            at_scope = all(kind == "scope" for kind, _, _ in stack)
            if not at_scope or re.search(r"\benum\b", head):
                stack.append(("block", line, ""))
            elif _SIGNATURE_END.search(head):
                name = re.findall(r"([~\w:]+(?:\s*operator\s*\S+?)?)\s*\(", head)
                stack.append(("function", line, name[0] if name else head[-40:]))
            elif re.search(r"\b(namespace|struct|class|union)\b", head):
                stack.append(("scope", line, ""))
            else:
                stack.append(("block", line, ""))
            last = i + 1
        elif c == "}":
            kind, start, name = stack.pop()
            if kind == "function":
                yield name, line - start + 1
            last = i + 1
        elif c == ";":
            last = i + 1
    assert not stack, "unbalanced braces"


def test_core_files_and_functions_are_small():
    files = sorted(p for p in CORE.iterdir() if p.suffix in (".hpp", ".cpp"))
    assert len(files) > 20, files
    big = []
    for p in files:
        if p.name in CPP_NOT_YET:
            continue
        text = p.read_text()
        if len(text.splitlines()) > MAX_MODULE_LINES:
            big.append((p.name, len(text.splitlines())))
        for name, n in _cpp_functions(text):
            if n > MAX_FUNCTION_LINES:
                big.append((f"{p.name}:{name}", n))
    assert not big, big


def test_the_core_scan_finds_functions():
    # the scan sees a long function, a method, a template and skips enums and literals
    src = (
        "namespace mk {\nenum E { A, B };\nstruct S {\n  int f(int a) const {\n"
        + '    auto g = [&]() { return "}"; };\n' * 3
        + "    return a;\n  }\n};\ntemplate <class T>\ninline T h(T x) { return x; }\n}\n"
    )
    assert list(_cpp_functions(src)) == [("f", 6), ("h", 1)]


def test_the_command_line_is_one_package_without_a_circle():
    loose = [name for name, _ in _modules() if re.match(r"_cli_|animation/cli", name)]
    assert not loose, loose
    for name, p in _modules():
        if name.startswith("cli/") and name != "cli/__init__.py":
            assert "from . import" not in _code(p.read_text()), name
