#!/usr/bin/env python3
"""Lists the `pub fn`s of the library (src/, without the binary's cli/ and main.rs) whose own doc
comment cites no equation or section of the paper ("(36)", "(39)-(42)", "section 6", ...).

Issue 17 asks every public item to state the paper's equation it implements (or that it
implements none) and its accuracy; this is the crude check behind that count. A module whose
items implement no formula of the paper says so once in its module docs, with their accuracy
("No item of this module implements a formula of the paper: ...", as src/estimate.rs does), and
its functions count as covered.

    python3 tools/scan_doc_equations.py          # the count, then every function lacking a citation
"""
import glob
import re

CITE = re.compile(r"\(\d{1,2}[a-z]?\)|eq\.|equation|section", re.I)
NONE = re.compile(r"No item of this module implements a formula of the paper")


def scan():
    total, missing = 0, []
    for f in sorted(glob.glob("src/**/*.rs", recursive=True)):
        if "/cli/" in f or f.endswith("main.rs"):
            continue
        lines = open(f, encoding="utf-8").read().split("\n")
        module_doc = " ".join(l[3:].strip() for l in lines if l.startswith("//!"))
        module_none = bool(NONE.search(module_doc))
        for i, line in enumerate(lines):
            m = re.match(r"\s*pub fn (\w+)", line)
            if not m:
                continue
            j, doc = i - 1, []
            while j >= 0 and lines[j].strip().startswith(("///", "#[")):
                doc.append(lines[j])
                j -= 1
            total += 1
            if not module_none and not CITE.search(" ".join(doc)):
                missing.append(f"{f}:{i + 1}: {m.group(1)}")
    return total, missing


if __name__ == "__main__":
    total, missing = scan()
    print(f"{total - len(missing)} of {total} pub fns cite an equation or section")
    for m in missing:
        print(m)
