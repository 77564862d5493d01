"""Tests of values.py (CI runs `python3 tools/values/test_values.py`): an output's entry is
spliced into values.json without touching the bytes of any other entry."""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from values import splice  # noqa: E402

# serde_json writes 1e-5 where Python writes 1e-05: another entry must keep serde's text.
TEXT = """{
  "a": {
    "file": "a.md",
    "values": {
      "x": {
        "shown": "0.00001",
        "number": 1e-5
      }
    }
  },
  "c": {
    "file": "c.md"
  }
}
"""

out = splice(TEXT, "b", {"file": "b.md", "values": {"y": {"shown": "2", "number": 2.0}}})
assert '"number": 1e-5' in out, out
assert list(json.loads(out)) == ["a", "b", "c"], out
again = splice(out, "b", {"file": "b.md"})
assert json.loads(again)["b"] == {"file": "b.md"} and '"number": 1e-5' in again, again
assert splice(TEXT, "a", json.loads(TEXT)["a"]).replace("1e-05", "1e-5") == TEXT
assert json.loads(splice("{}\n", "a", {"file": "a.md"})) == {"a": {"file": "a.md"}}
print("values.py: 4 checks pass")
