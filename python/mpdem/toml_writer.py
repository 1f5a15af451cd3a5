"""TOML text of a scene document (dict): the writer behind Scene.to_toml.

Tables become ``[name]`` sections, lists of tables ``[[name]]``; tables nested in a list entry
are written inline. Floats are written with repr(), the shortest text that reads back as the
same double, so a scene written and read again is the same scene bit for bit.
"""

import math
import numbers

__all__ = ["dumps"]


def _plain(value):
    """numpy scalars and arrays as Python numbers and lists."""
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        return value.tolist()
    return value


def _string(s):
    out = ['"']
    for ch in s:
        code = ord(ch)
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif code < 0x20 or code == 0x7F:
            out.append("\\u%04X" % code)
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _key(k):
    if not isinstance(k, str):
        raise TypeError(f"TOML keys are strings, got {k!r}")
    if k and all(c.isalnum() and c.isascii() or c in "_-" for c in k):
        return k
    return _string(k)


def value(v, where="value"):
    """One TOML value: a number, bool, string, list or (inline) table."""
    v = _plain(v)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        f = float(v)
        if math.isnan(f):
            return "nan"
        if math.isinf(f):
            return "inf" if f > 0 else "-inf"
        return repr(f)
    if isinstance(v, str):
        return _string(v)
    if hasattr(v, "__fspath__"):
        return _string(str(v))
    if isinstance(v, dict):
        items = ", ".join(f"{_key(k)} = {value(x, k)}" for k, x in v.items() if x is not None)
        return "{ " + items + " }" if items else "{}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(x, where) for x in v) + "]"
    raise TypeError(f"'{where}': cannot write {type(v).__name__} {v!r} as a TOML value")


def _is_table_list(v):
    v = _plain(v)
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _table(lines, path, table):
    """Section [path]: its plain keys, then its sub-tables and lists of tables."""
    plain = {k: v for k, v in table.items() if v is not None and not isinstance(v, dict) and not _is_table_list(v)}
    nested = {k: v for k, v in table.items() if isinstance(v, dict)}
    lists = {k: v for k, v in table.items() if _is_table_list(v)}
    if plain or not (nested or lists):
        lines.append(f"[{path}]")
        for k, v in plain.items():
            lines.append(f"{_key(k)} = {value(v, path + '.' + k)}")
        lines.append("")
    for k, v in nested.items():
        _table(lines, f"{path}.{_key(k)}", v)
    for k, entries in lists.items():
        for entry in entries:
            _entry(lines, f"{path}.{_key(k)}", entry)


def _entry(lines, path, entry):
    """One [[path]] entry: every key on its own line, nested tables inline."""
    lines.append(f"[[{path}]]")
    for k, v in entry.items():
        if v is not None:
            lines.append(f"{_key(k)} = {value(v, path + '.' + k)}")
    lines.append("")


def dumps(document, header=None):
    """The TOML text of `document`: top-level plain keys, tables, then lists of tables."""
    lines = []
    if header:
        lines.extend("# " + h for h in header.splitlines())
        lines.append("")
    for k, v in document.items():
        if v is not None and not isinstance(v, dict) and not _is_table_list(v):
            lines.append(f"{_key(k)} = {value(v, k)}")
    for k, v in document.items():
        if isinstance(v, dict):
            _table(lines, _key(k), v)
    for k, v in document.items():
        if _is_table_list(v):
            for entry in v:
                _entry(lines, _key(k), entry)
    return "\n".join(lines).rstrip("\n") + "\n"
