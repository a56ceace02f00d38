#!/usr/bin/env python3
"""Counts the library's public surface twice, from rustdoc's JSON output (format 57, rustc's
unstable `--output-format json`, enabled on stable with RUSTC_BOOTSTRAP=1):

* documented: the items rustdoc shows (hidden items stripped, as on docs.rs);
* declared:   every item declared `pub` in a module reachable from the crate root, including
              those under `#[doc(hidden)]` (rustdoc's `--document-hidden-items`).

Items are counted where they are declared (a `pub use` re-export is not a second item), in two
kinds: module-level items (modules, structs, enums, unions, traits, functions, constants,
statics, type aliases, macros) and the associated items of their inherent impls (methods and
associated constants; trait impls are not counted). A difference between the two counts is
public API that the documentation does not show.

Usage: python3 tools/public_surface.py   (from the repository root; runs cargo rustdoc twice,
about a minute each on two cores).
"""
import json
import os
import subprocess
import sys

MODULE_LEVEL = {"module", "struct", "enum", "union", "trait", "function", "constant",
                "static", "type_alias", "macro", "proc_macro"}


def rustdoc_json(hidden):
    args = ["cargo", "rustdoc", "--release", "--lib", "--quiet", "--",
            "-Z", "unstable-options", "--output-format", "json"]
    if hidden:
        args.append("--document-hidden-items")
    env = dict(os.environ, RUSTC_BOOTSTRAP="1")
    subprocess.run(args, check=True, env=env)
    target = os.environ.get("CARGO_TARGET_DIR", "target")
    with open(os.path.join(target, "doc", "moving_hertz.json")) as f:
        return json.load(f)


def count(doc):
    index = doc["index"]
    seen, items, assoc = set(), 0, 0
    stack = [doc["root"]]
    while stack:
        iid = stack.pop()
        if iid in seen or str(iid) not in index:
            continue
        seen.add(iid)
        item = index[str(iid)]
        if item["crate_id"] != 0:
            continue
        (kind, inner), = item["inner"].items()
        if kind in MODULE_LEVEL:
            items += 1
        if kind == "module":
            stack.extend(inner["items"])
        elif kind in ("struct", "enum", "union"):
            for impl_id in inner.get("impls", []):
                impl = index.get(str(impl_id))
                if impl is None:
                    continue
                body = impl["inner"]["impl"]
                if body["trait"] is None and not body.get("is_synthetic"):
                    assoc += sum(1 for a in body["items"] if str(a) in index)
    return items, assoc


def main():
    documented = count(rustdoc_json(hidden=False))
    declared = count(rustdoc_json(hidden=True))
    print(f"documented (rustdoc shows): {documented[0]} items, {documented[1]} inherent associated items")
    print(f"declared pub (reachable):   {declared[0]} items, {declared[1]} inherent associated items")
    print(f"hidden: {declared[0] - documented[0]} items, {declared[1] - documented[1]} associated items")


if __name__ == "__main__":
    sys.exit(main())
