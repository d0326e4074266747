#!/usr/bin/env python3
"""Measures the code's text as issue 23 asks: file-level import cycles (between the
.rs files of one crate, following `pub use` re-exports to the file that defines the
name, each facade passed on the way an edge too, but the crate root and a folder's
mod.rs seen from inside the folder), functions over 80 lines (a `;` in a signature's
brackets, as in `-> [f64; 2]`, is no declaration; tests in test_code_measures.py),
functions returning `Result<_, String>`, and the app state's fields. Reads source, builds nothing. Test code (`#[cfg(test)]` modules and
`tests/`) is left out of the function counts, as it is of the product.

    python3 scripts/code_measures.py            # the summary
    python3 scripts/code_measures.py --mermaid linkage   # a crate's module graph
    python3 scripts/code_measures.py --check    # CI: no cycle, docs/architecture.md true
    python3 scripts/code_measures.py --write-doc  # the graphs in docs/architecture.md anew
    python3 scripts/code_measures.py --list     # and every cycle (with its edges),
                                                # long function and Result<_, String>
"""
import functools
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CRATES = {"linkage-lab": ROOT / "src"} | {
    p.name: p / "src" for p in sorted((ROOT / "crates").iterdir()) if (p / "src").is_dir()
}
LONG = 80
# The functions allowed over LONG lines, each with its reason: one
# "path name" (no line number) to its reason. Kept short: --check fails on a long
# function not listed and on an entry that is no longer long.
LONG_ALLOWED = {
    "crates/linkage-cli/src/plot.rs work_precision_png":
        "one plotters chart built in one chain (axes, series, legend)",
    "crates/linkage-diagram/src/construction.rs construct":
        "the textbook's graphical construction step by step, in drawing order",
    "crates/linkage/src/solve/closed_form/mod.rs decompose":
        "one search loop over the dyads, its six pieces of state shared by every step",
    "src/render/wgpu_pipeline.rs install":
        "one wgpu pipeline's descriptors, each a literal the next refers to",
}
# Folders drawn file by file in the module graphs (the app's panels).
FILE_LEVEL = {"ui"}


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return "\n".join(re.sub(r"//.*", "", line) for line in text.split("\n"))


def strip_tests(text):
    """The text without `#[cfg(test)] mod x { ... }` blocks (lines kept blank)."""
    lines = text.split("\n")
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() == "#[cfg(test)]" and i + 1 < len(lines) and re.match(r"\s*mod \w+ \{", lines[i + 1]):
            depth, j = 0, i + 1
            while j < len(lines):
                depth += lines[j].count("{") - lines[j].count("}")
                if depth == 0:
                    break
                j += 1
            out += [""] * (j - i + 1)
            i = j + 1
            continue
        out.append(lines[i])
        i += 1
    return "\n".join(out)


def module_of(src, f):
    rel = f.relative_to(src).with_suffix("")
    parts = list(rel.parts)
    if parts in (["lib"], ["main"]):
        return ()
    if parts[-1] == "mod":
        parts = parts[:-1]
    return tuple(parts)


def use_paths(text):
    """Every path a `use` names, its braces expanded, and every `crate::`/`super::`
    path written inline."""
    paths = []

    def expand(prefix, body):
        depth, start = 0, 0
        items = []
        for k, ch in enumerate(body):
            if ch == "{":
                depth += 1
            elif ch == "}":
                depth -= 1
            elif ch == "," and depth == 0:
                items.append(body[start:k])
                start = k + 1
        items.append(body[start:])
        for item in items:
            item = item.strip()
            if not item:
                continue
            m = re.match(r"^([\w:]*?)::\{(.*)\}$", item, flags=re.S)
            if m:
                expand(prefix + m.group(1).split("::"), m.group(2))
            elif item.startswith("{"):
                expand(prefix, item[1:-1])
            else:
                name = re.split(r"\s+as\s+", item)[0].strip()
                paths.append(prefix + [s for s in name.split("::") if s])

    # A `pub use` is a facade: followed to the file that defines the name, no edge.
    for m in re.finditer(r"(\bpub(?:\([\w:]+\))?\s+)?\buse\s+([^;]+);", text):
        if not m.group(1):
            expand([], m.group(2))
    for m in re.finditer(r"\b((?:crate|super)(?:::\w+)+)", text):
        paths.append(m.group(1).split("::"))
    return paths


@functools.cache
def crate_graph(src):
    """Which file of the crate in `src` uses which: {file: {files}}. Cached: --check
    asks for each crate's graph for its cycles, its layers and its drawn graph."""
    files = sorted(src.rglob("*.rs"))
    is_bin_root = {src / "main.rs"} if (src / "lib.rs").exists() else set()
    mods = {module_of(src, f): f for f in files if f not in is_bin_root}
    # Test modules are left out: a test may reach anywhere in its crate.
    texts = {f: strip_tests(strip_comments(f.read_text())) for f in files}
    reexports = {}
    for mod, f in mods.items():
        for m in re.finditer(r"\bpub(?:\([\w:]+\))?\s+use\s+([^;]+);", texts[f]):
            for p in use_paths("use " + m.group(1) + ";"):  # noqa: the facade itself
                reexports[(mod, p[-1])] = p

    def absolute(mod, path):
        path = list(path)
        base = list(mod)
        if path[0] == "crate":
            base, path = [], path[1:]
        elif path[0] in ("super", "self"):
            while path and path[0] in ("super", "self"):
                if path[0] == "super":
                    base = base[:-1]
                path = path[1:]
        elif tuple(base + [path[0]]) in mods:
            pass
        else:
            return None
        return base + path

    def target(user, mod, path, seen=0):
        """The files a use of `path` in module `mod` makes module `user` depend on:
        the file that defines the name and every facade passed on the way (a `pub
        use` in another module is an edge too: `use crate::model::SceneProblem` leans
        on model/mod.rs whatever file defines the name). Two facades are no edge: the
        crate root (every `crate::X` would run through it) and a module `user` is
        inside (a child naming a sibling through its folder's mod.rs)."""
        full = absolute(mod, path)
        if full is None or seen > 8:
            return []
        for n in range(len(full), -1, -1):
            if tuple(full[:n]) in mods:
                owner = tuple(full[:n])
                if n < len(full) and (owner, full[n]) in reexports:
                    # Followed to where it is defined; none when another crate's.
                    inside = owner == () or user[: len(owner)] == owner
                    facade = [] if inside else [mods[owner]]
                    return facade + target(user, owner, reexports[(owner, full[n])], seen + 1)
                return [mods[owner]]
        return []

    edges = {f: set() for f in files}
    for f in files:
        if f in is_bin_root:
            continue
        mod = module_of(src, f)
        paths = use_paths(texts[f])
        # A module brought in by `use` (`use crate::ui;`) is then named inline
        # (`ui::plots::panel(..)`): those paths count too.
        # Child modules declared here are named inline too (`commands::run(..)`).
        aliases = {
            m.group(1): list(mod) + [m.group(1)]
            for m in re.finditer(r"^\s*(?:pub(?:\([\w:]+\))?\s+)?mod (\w+);", texts[f], re.M)
            if tuple(list(mod) + [m.group(1)]) in mods
        }
        for p in paths:
            full = absolute(mod, p)
            if full and tuple(full) in mods and tuple(full) != mod[: len(full)]:
                aliases[p[-1]] = full
        # A facade (`pub use edit::SceneEdit;`) names no use of its own.
        body = re.sub(r"\bpub(?:\([\w:]+\))?\s+use\s+[^;]+;", "", texts[f])
        for alias, full in aliases.items():
            for m in re.finditer(rf"(?<![\w:]){alias}((?:::\w+)+)", body):
                paths.append(["crate"] + full + m.group(1).split("::")[1:])
        for p in paths:
            edges[f].update(t for t in target(mod, mod, p) if t != f)
    return edges


def cycles(edges):
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]
    sys.setrecursionlimit(10000)

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in edges:
        if v not in index:
            visit(v)
    return out


def body_start(lines, i, column):
    """Where the body of the `fn` whose signature starts at line `i`, column
    `column`, opens: (line, column) of its `{`, or None for a declaration without a
    body. A `;` ends the signature only outside brackets: `-> [f64; 2]` is a type."""
    nest = 0
    for j in range(i, len(lines)):
        for k, ch in enumerate(lines[j][column if j == i else 0:], column if j == i else 0):
            if ch in "([":
                nest += 1
            elif ch in ")]":
                nest -= 1
            elif nest == 0 and ch == "{":
                return j, k
            elif nest == 0 and ch == ";":
                return None
    return None


def functions(text):
    """Each function with a body: its name, first line and length in lines."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        m = re.match(r"\s*(?:pub(?:\([\w:]+\))?\s+)?(?:const\s+)?(?:async\s+)?fn\s+(\w+)", line)
        if not m:
            continue
        start = body_start(lines, i, m.end())
        if start is None:
            continue
        j0, k0 = start
        depth = 0
        for j in range(j0, len(lines)):
            depth += lines[j][k0 if j == j0 else 0:].count("{") - lines[j][k0 if j == j0 else 0:].count("}")
            if depth <= 0:
                yield m.group(1), i + 1, j - i + 1
                break


def top_module(src, f):
    """The module `f` belongs to in a module graph: its top module (a folder counted
    as one, but the app's panels file by file), `lib` or `main` for the roots."""
    mod = module_of(src, f)
    if len(mod) > 1 and mod[0] in FILE_LEVEL:
        return "/".join(mod[:2])
    return mod[0] if mod else ("main" if f.name == "main.rs" else "lib")


def module_edges(crate):
    """Which top module uses which, the library root left out (every path runs
    through it): {(user, used)}."""
    src = CRATES[crate]
    graph = crate_graph(src)
    top = lambda f: top_module(src, f)  # noqa: E731
    return {
        (top(a), top(b))
        for a in graph
        for b in graph[a]
        if top(a) != top(b) and "lib" not in (top(a), top(b))
    }


def mermaid(crate):
    """The crate's modules (a folder counted as one) and which uses which, as a
    mermaid graph."""
    name = lambda m: m.replace("/", "_")  # noqa: E731  mermaid ids take no slash
    lines = ["graph TD"] + [
        f"    {name(a)}[{a}] --> {name(b)}[{b}]" for a, b in sorted(module_edges(crate))
    ]
    return "\n".join(lines)


def doc_layers(doc, crate, modules):
    """The layers docs/architecture.md draws for `crate` ({module: layer number}),
    read from the numbered list after "In layers" in the crate's section: a
    backticked name that is one of the crate's `modules` belongs to the item it is
    first named in (a later item may name a submodule of the same name, as
    synthesis's `motion`). None when the section draws no layers."""
    section = re.search(rf"^## [^\n]*\(`crates/{crate}`\)\n(.*?)(?=^## )", doc, re.S | re.M)
    if not section or "In layers" not in section.group(1):
        return None
    layers = {}
    items = re.findall(r"^(\d+)\. (.*?)(?=^\d+\. |^\s*$)", section.group(1), re.S | re.M)
    for number, text in items:
        for name in re.findall(r"`([\w/]+)`", text):
            name = name.rstrip("/")
            if name in modules and name not in layers:
                layers[name] = int(number)
    return layers


def layer_faults(edges, modules, layers):
    """What breaks the drawn layers: a module in no layer, an edge from a lower
    layer to a higher one, and a cycle between modules (of one layer: an upward edge
    is reported as such). Each as a line to print."""
    faults = [f"{m}: in no layer of docs/architecture.md" for m in sorted(modules - set(layers))]
    faults += [
        f"upward edge: {a} (layer {layers[a]}) uses {b} (layer {layers[b]})"
        for a, b in sorted(edges)
        if a in layers and b in layers and layers[a] < layers[b]
    ]
    graph = {m: set() for m in modules}
    for a, b in edges:
        graph.setdefault(a, set()).add(b)
        graph.setdefault(b, set())
    faults += ["module cycle: " + " <-> ".join(c) for c in cycles(graph)]
    return faults


def long_functions():
    """Every function over LONG lines outside tests: [(lines, "path:line name")]."""
    found = []
    for src in CRATES.values():
        for f in sorted(src.rglob("*.rs")):
            text = strip_tests(strip_comments(f.read_text()))
            rel = f.relative_to(ROOT)
            for fn, line, n in functions(text):
                if n > LONG:
                    found.append((n, f"{rel}:{line} {fn}"))
    return found


def long_faults(found, allowed):
    """A long function not in `allowed` ({"path name": reason}), and an entry of
    `allowed` that names no long function (stale: the allow-list stays short and
    true). Each as a line to print."""
    named = {re.sub(r":\d+ ", " ", where) for _, where in found}
    faults = [
        f"function over {LONG} lines, not allowed: {where} ({n} lines)"
        for n, where in sorted(found, reverse=True)
        if re.sub(r":\d+ ", " ", where) not in allowed
    ]
    faults += [f"allowed long function no longer long (drop it): {a}" for a in sorted(allowed) if a not in named]
    return faults


def broken_links(markdown):
    """The relative links and images of `markdown` files ({path: text}) whose target
    does not exist, as "file: target" (web links, mail and in-page anchors left
    out; a target's own #anchor is dropped)."""
    broken = []
    for path, text in markdown.items():
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            if not (path.parent / target.split("#")[0]).exists():
                broken.append(f"{path.relative_to(ROOT)}: {target}")
    return broken


def check():
    """Exit status 1 when a file-level import cycle exists, the solver's modules
    break the layers docs/architecture.md draws, a function is over LONG lines
    without a reason in LONG_ALLOWED, a relative link in README.md or docs/ leads
    nowhere, or a module graph in the doc no longer matches the code."""
    faults = []
    for name, src in CRATES.items():
        for comp in cycles(crate_graph(src)):
            faults.append("import cycle: " + " <-> ".join(str(f.relative_to(ROOT)) for f in comp))
    doc = (ROOT / "docs/architecture.md").read_text()
    for name, src in CRATES.items():
        modules = {top_module(src, f) for f in src.rglob("*.rs")} - {"lib", "main"}
        layers = doc_layers(doc, name, modules)
        if layers is not None:
            edges = {(a, b) for a, b in module_edges(name) if "main" not in (a, b)}
            faults += [f"{name}: {x}" for x in layer_faults(edges, modules, layers)]
    faults += long_faults(long_functions(), LONG_ALLOWED)
    markdown = {p: p.read_text() for p in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]}
    faults += [f"broken link: {b}" for b in broken_links(markdown)]
    for m in re.finditer(r"<!-- crate: ([\w-]+) -->\n```mermaid\n(.*?)\n```", doc, re.S):
        if m.group(2).strip() != mermaid(m.group(1)).strip():
            faults.append(f"docs/architecture.md: the graph of {m.group(1)} is out of date "
                          "(python3 scripts/code_measures.py --write-doc rewrites them)")
    for fault in faults:
        print(fault)
    sys.exit(1 if faults else 0)


def write_doc():
    """Rewrites the module graphs in docs/architecture.md from the code."""
    path = ROOT / "docs/architecture.md"
    doc = path.read_text()
    doc = re.sub(
        r"<!-- crate: ([\w-]+) -->\n```mermaid\n(.*?)\n```",
        lambda m: f"<!-- crate: {m.group(1)} -->\n```mermaid\n{mermaid(m.group(1))}\n```",
        doc,
        flags=re.S,
    )
    path.write_text(doc)


def main():
    if "--write-doc" in sys.argv:
        write_doc()
        return
    if "--check" in sys.argv:
        check()
    if "--mermaid" in sys.argv:
        print(mermaid(sys.argv[sys.argv.index("--mermaid") + 1]))
        return
    listing = "--list" in sys.argv
    all_cycles, long_fns, string_results, cycle_edges = [], [], [], []
    for name, src in CRATES.items():
        graph = crate_graph(src)
        for comp in cycles(graph):
            all_cycles.append([str(f.relative_to(ROOT)) for f in comp])
            members = set(comp)
            cycle_edges += [
                f"{a.relative_to(ROOT)} -> {b.relative_to(ROOT)}"
                for a in comp
                for b in sorted(graph[a])
                if b in members
            ]
        for f in sorted(src.rglob("*.rs")):
            text = strip_tests(strip_comments(f.read_text()))
            rel = f.relative_to(ROOT)
            for m in re.finditer(r"Result<[^;{]*?,\s*String\s*>", text):
                string_results.append(f"{rel}:{text[:m.start()].count(chr(10)) + 1}")
    long_fns = long_functions()
    app_state = re.search(r"pub struct AppState \{(.*?)\n\}", (ROOT / "src/state.rs").read_text(), re.S)
    fields = len(re.findall(r"^\s*pub \w+:", app_state.group(1), re.M)) if app_state else 0
    tests = [p for p in (ROOT / "tests").iterdir() if p.suffix == ".rs" or (p / "main.rs").exists()]
    print(f"import cycles: {len(all_cycles)} over {sum(map(len, all_cycles))} files")
    print(f"functions over {LONG} lines: {len(long_fns)}")
    print(f"Result<_, String>: {len(string_results)}")
    print(f"AppState public fields: {fields}")
    print(f"app test binaries: {len(tests)}")
    if listing:
        for c in all_cycles:
            print("cycle:", " <-> ".join(c))
        for e in cycle_edges:
            print("  edge:", e)
        for n, where in sorted(long_fns, reverse=True):
            print(f"long: {n:4} {where}")
        for where in string_results:
            print("string error:", where)


if __name__ == "__main__":
    main()
