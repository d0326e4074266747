#!/usr/bin/env python3
"""Tests of scripts/code_measures.py on small crates written to a temporary folder:
each case one of the script's former blind spots (a cycle through a `pub use`
facade, a `;` inside a signature's brackets) or a facade that is rightly no edge,
and the checks CI runs (the drawn layers, the long functions' allow-list).

    python3 scripts/test_code_measures.py
"""
import tempfile
import unittest
from pathlib import Path

import code_measures as cm


def crate(files):
    """A crate's src folder holding `files` ({relative path: text})."""
    src = Path(tempfile.mkdtemp()) / "src"
    for rel, text in files.items():
        path = src / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return src


def named_cycles(src):
    graph = cm.crate_graph(src)
    return [sorted(str(f.relative_to(src)) for f in comp) for comp in cm.cycles(graph)]


def named_edges(src, rel):
    graph = cm.crate_graph(src)
    return sorted(str(t.relative_to(src)) for t in graph[src / rel])


class Facades(unittest.TestCase):
    def test_a_cycle_through_a_facade_is_found(self):
        # s.rs names P through m's facade, and m/mod.rs uses s: m and s use each
        # other, though P is defined in m/p.rs (the script missed this).
        src = crate({
            "lib.rs": "mod m;\nmod s;\n",
            "m/mod.rs": "mod p;\npub use p::P;\nuse crate::s::S;\n",
            "m/p.rs": "pub struct P;\n",
            "s.rs": "use crate::m::P;\npub struct S;\n",
        })
        self.assertEqual(named_cycles(src), [["m/mod.rs", "s.rs"]])

    def test_the_crate_root_is_no_edge(self):
        src = crate({
            "lib.rs": "mod a;\nmod b;\npub use a::A;\n",
            "a.rs": "pub struct A;\n",
            "b.rs": "use crate::A;\npub struct B;\n",
        })
        self.assertEqual(named_edges(src, "b.rs"), ["a.rs"])
        self.assertEqual(named_cycles(src), [])

    def test_a_child_through_its_own_folders_facade_is_no_edge(self):
        # c.rs names its sibling's D through the folder's mod.rs, which uses c: the
        # folder's index, not a cycle.
        src = crate({
            "lib.rs": "mod x;\n",
            "x/mod.rs": "mod c;\nmod d;\npub use d::D;\nfn f() { c::g(); }\n",
            "x/c.rs": "use super::D;\npub fn g() {}\n",
            "x/d.rs": "pub struct D;\n",
        })
        self.assertEqual(named_edges(src, "x/c.rs"), ["x/d.rs"])
        self.assertEqual(named_cycles(src), [])


class Functions(unittest.TestCase):
    def lengths(self, text):
        return {name: (line, n) for name, line, n in cm.functions(text)}

    def test_a_bracketed_semicolon_in_a_signature_is_no_declaration(self):
        # The script stopped at the `;` of `[f64; 2]` and lost the function.
        body = "\n".join(f"    let x{k} = {k};" for k in range(83))
        text = "pub fn layout(\n    measure: &dyn Fn(u8) -> [f64; 2],\n) -> u8 {\n" + body + "\n    0\n}\n"
        self.assertEqual(self.lengths(text), {"layout": (1, 88)})

    def test_a_declaration_has_no_body_and_the_next_function_is_counted(self):
        body = "\n".join("    let _ = 1;" for _ in range(88))
        text = "trait T {\n    fn f(&self) -> [f64; 2];\n}\nfn g() {\n" + body + "\n}\n"
        self.assertEqual(self.lengths(text), {"g": (4, 90)})

    def test_a_one_line_function_with_an_array_argument_is_counted(self):
        text = "fn h(a: [u8; 4]) -> u8 { a[0] }\n"
        self.assertEqual(self.lengths(text), {"h": (1, 1)})


DOC = """## The solver (`crates/demo`)

In layers, each using only those below it:

1. leaves: `e` (the errors; not `Thing`),
   `u`;
2. the model: `hi/` (with its own `e`), `mid`;

The folders keep their files private.

## The next section
"""


class Layers(unittest.TestCase):
    def test_the_numbered_list_gives_each_module_its_first_layer(self):
        layers = cm.doc_layers(DOC, "demo", {"e", "u", "hi", "mid", "other"})
        self.assertEqual(layers, {"e": 1, "u": 1, "hi": 2, "mid": 2})
        self.assertIsNone(cm.doc_layers(DOC, "another", {"e"}))

    def test_a_leaf_that_uses_a_higher_layer_is_an_upward_edge(self):
        # The leaf e re-exported hi's type: the doc drew e as a leaf all the same.
        src = crate({
            "lib.rs": "mod e;\nmod hi;\nmod u;\nmod mid;\n",
            "e.rs": "pub use crate::hi::T;\n",
            "hi/mod.rs": "pub struct T;\n",
            "u.rs": "",
            "mid.rs": "use crate::u;\n",
        })
        cm.CRATES["demo"] = src
        try:
            edges = cm.module_edges("demo")
        finally:
            del cm.CRATES["demo"]
        modules = {"e", "hi", "u", "mid"}
        faults = cm.layer_faults(edges, modules, cm.doc_layers(DOC, "demo", modules))
        self.assertEqual(faults, ["upward edge: e (layer 1) uses hi (layer 2)"])

    def test_a_module_in_no_layer_and_a_cycle_in_one_layer_fail(self):
        faults = cm.layer_faults({("a", "b"), ("b", "a")}, {"a", "b", "c"}, {"a": 1, "b": 1})
        self.assertEqual(faults, ["c: in no layer of docs/architecture.md", "module cycle: a <-> b"])


class LongFunctions(unittest.TestCase):
    def test_an_unlisted_long_function_and_a_stale_entry_fail(self):
        found = [(90, "src/a.rs:10 long_one"), (85, "src/b.rs:3 listed")]
        allowed = {"src/b.rs listed": "why", "src/c.rs gone": "was long once"}
        self.assertEqual(cm.long_faults(found, allowed), [
            "function over 80 lines, not allowed: src/a.rs:10 long_one (90 lines)",
            "allowed long function no longer long (drop it): src/c.rs gone",
        ])

    def test_a_listed_long_function_passes_wherever_its_line_moves(self):
        self.assertEqual(cm.long_faults([(99, "src/b.rs:77 listed")], {"src/b.rs listed": "why"}), [])


class Links(unittest.TestCase):
    def test_a_link_from_inside_docs_resolves_from_there(self):
        # docs/journal.md linked tests/snapshots/... as if from the repository's root.
        root = Path(tempfile.mkdtemp())
        (root / "docs").mkdir()
        (root / "tests").mkdir()
        (root / "tests" / "shot.png").write_text("")
        doc = root / "docs" / "journal.md"
        text = "![](tests/shot.png) ![](../tests/shot.png) [web](https://x.org/a) [here](#top)"
        old_root, cm.ROOT = cm.ROOT, root
        try:
            self.assertEqual(cm.broken_links({doc: text}), ["docs/journal.md: tests/shot.png"])
        finally:
            cm.ROOT = old_root


if __name__ == "__main__":
    unittest.main()
