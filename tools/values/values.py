"""The book's named values from a Python tool (tools/mitsuba, tools/mutants): the same file,
figures/values.json, and the same rules as the Rust figure job's `raylemma_values::Record`
(tools/values/src/lib.rs), whose reader, the book builder, checks them.

    from values import Record
    r = Record("mitsuba_compare.md")
    r.number("cornell.mean_z2", 1.141, ".3")   # returns "1.141", the text the table prints
    r.claim("every_scene_agrees", all_agree, "cornell agree, ...")
    r.write(root, table_text)                   # replaces this output's entry in values.json
"""
import json
import math
import os
import re

NAME = re.compile(r"^[a-z0-9_]+(\.[a-z0-9_]+)*$")


def slug(label):
    """A label as one word of a name, as raylemma_values::slug makes it."""
    return re.sub(r"_+", "_", re.sub(r"[^a-z0-9]", "_", label.lower())).strip("_")


def _round(v):
    """Half away from zero, as Rust's f64::round (Python's round() is half to even)."""
    return math.copysign(math.floor(abs(v) + 0.5), v)


def format_number(x, fmt):
    """`int`, `.N`, `sN` or `xN`, as raylemma_values::format_number."""
    if not math.isfinite(x):
        return {True: "inf", False: "-inf"}.get(x > 0, "NaN") if not math.isnan(x) else "NaN"
    if fmt == "int":
        return f"{x:.0f}"
    if fmt.startswith("."):
        return f"{x:.{int(fmt[1:])}f}"
    if fmt.startswith("s"):
        n = max(int(fmt[1:]), 1)
        if x == 0:
            return "0"
        e = math.floor(math.log10(abs(x)))
        rounded = _round(x / 10.0 ** (e - n + 1)) * 10.0 ** (e - n + 1)
        if abs(rounded) >= 10.0 ** (e + 1):  # rounding carried into the next power of ten
            e += 1
            rounded = _round(x / 10.0 ** (e - n + 1)) * 10.0 ** (e - n + 1)
        decimals = max(n - 1 - e, 0)
        return f"{rounded:.{decimals}f}"
    if fmt.startswith("x"):
        m, e = f"{x:.{int(fmt[1:])}e}".split("e")
        return m if int(e) == 0 else f"{m}\\times10^{{{int(e)}}}"
    raise ValueError(f"unknown format {fmt!r} (int, .N, sN or xN)")


class Record:
    def __init__(self, file):
        self.file = file
        self.values = {}
        self.claims = {}

    def _name(self, name):
        if not NAME.match(name):
            raise ValueError(f"{name!r} is not a value name")
        if name in self.values or name in self.claims:
            raise ValueError(f"{name!r} is recorded twice")

    def number(self, name, x, fmt):
        self._name(name)
        shown = format_number(float(x), fmt)
        self.values[name] = {"shown": shown}
        if math.isfinite(x):
            self.values[name]["number"] = float(x)
        return shown

    def text(self, name, shown):
        self._name(name)
        self.values[name] = {"shown": shown}
        return shown

    def claim(self, name, holds, read):
        self._name(name)
        self.claims[name] = {"holds": bool(holds), "read": read}

    def write(self, root, table, quick=False):
        """Puts this record into ROOT/figures/values.json (atomically), with the machine
        fingerprint that the table's caption names, if any."""
        path = os.path.join(root, "figures", "values.json")
        try:
            with open(path, encoding="utf-8") as f:
                values = json.load(f)
        except FileNotFoundError:
            values = {}
        entry = {"file": self.file}
        m = re.search(r"fingerprint `?([0-9a-f]{8})", table)
        if m:
            entry["machine"] = m.group(1)
        if quick:
            entry["quick"] = True
        if self.values:
            entry["values"] = dict(sorted(self.values.items()))
        if self.claims:
            entry["claims"] = dict(sorted(self.claims.items()))
        key = self.file.rsplit(".", 1)[0]
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except FileNotFoundError:
            text = "{}\n"
        tmp = path + ".tmp"
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(splice(text, key, entry))
        os.replace(tmp, path)


def splice(text, key, entry):
    """values.json's TEXT with the top-level entry KEY replaced by (or given) ENTRY, every
    other entry kept to the byte: Python writes floats otherwise than serde_json (1e-05 for
    1e-5), so rewriting the whole file would change numbers of outputs it never touched."""
    blocks = {}
    current = None
    for line in text.split("\n"):
        m = re.match(r'^  ("(?:[^"\\]|\\.)*"): ', line)
        if m:
            current = json.loads(m.group(1))
            blocks[current] = [line]
        elif current is not None and line.startswith("  "):
            blocks[current].append(line)
        else:
            current = None
    blocks = {k: "\n".join(v).rstrip(",") for k, v in blocks.items()}
    body = json.dumps(entry, indent=2, ensure_ascii=False).replace("\n", "\n  ")
    blocks[key] = f"  {json.dumps(key)}: {body}"
    return "{\n" + ",\n".join(blocks[k] for k in sorted(blocks)) + "\n}\n"
