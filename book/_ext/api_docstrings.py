"""The API reference (api.md) reads the docstrings as they are written: plain text for ``help()``.

Three things plain text does that reStructuredText reads otherwise:

- ``|H|``, ``|u − x|²``: bars are absolute values and norms, never reST substitutions. Bars are
  escaped before the docstring is parsed, except inside inline literals and roles, doctest lines and
  literal blocks, where reST does not read them.
- ``k_{p+1}``, ``R^{n+1}``: sub- and superscripts written as in LaTeX, which the page would show as
  raw LaTeX; outside literals they become reST's ``:sub:`` and ``:sup:`` (``k`` with ``p+1`` set
  lower), so the API page reads like the rest of the book while ``help()`` keeps the plain text.
- ``:func:`thesis_lib.morse.examples.rp2_chart```: a docstring may name an object by the module that
  defines it while the reference documents it where users import it from (its package,
  ``thesis_lib.morse.rp2_chart``). A ``thesis_lib.`` reference that finds no target is resolved to
  the documented name of the same object; a name that is not documented under any path still fails.
"""

from __future__ import annotations

import importlib
import re

# inline literals and roles (``x``, :math:`x`), left as they are
_PROTECTED = re.compile(r"``.+?``|:[\w:.-]+:`[^`]*`")


# a sub- or superscript written as in LaTeX after some base: k_{p+1}, R^{n+1}
_SCRIPT = re.compile(r"(?<=[^\s\\])([_^])\{([^{}`\n]+)\}")


def _prose(text: str) -> str:
    """Bars escaped, and ``_{…}`` / ``^{…}`` as reST subscripts and superscripts (``<sub>``, ``<sup>``)."""
    text = re.sub(r"(?<!\\)\|", r"\\|", text)
    return _SCRIPT.sub(lambda m: "\\ :" + ("sub" if m.group(1) == "_" else "sup") + ":`" + m.group(2) + "`\\ ", text)


def _escape_bars(text: str) -> str:
    out, end = [], 0
    for m in _PROTECTED.finditer(text):
        out.append(_prose(text[end:m.start()]))
        out.append(m.group(0))
        end = m.end()
    out.append(_prose(text[end:]))
    return "".join(out)


def escape_bars(lines: list[str]) -> None:
    """Escape the bars of ``lines`` in place and set their ``_{…}``/``^{…}`` as sub- and
    superscripts, outside inline literals, roles, literal blocks and doctests."""
    literal_indent = None  # indentation of the paragraph that opened a literal block (::)
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if literal_indent is not None:
            if not stripped or indent > literal_indent:
                continue
            literal_indent = None
        if stripped.startswith((">>>", "... ")):
            continue
        lines[i] = _escape_bars(line)
        if stripped.endswith("::"):
            literal_indent = indent


def _process_docstring(app, what, name, obj, options, lines) -> None:
    escape_bars(lines)


def _import(path: str):
    """The object at the dotted ``path`` (a module, or an attribute of one), or None."""
    parts = path.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        try:
            for attr in parts[i:]:
                obj = getattr(obj, attr)
        except AttributeError:
            return None
        return obj
    return None


def _documented(env) -> dict[int, str]:
    """id of each documented thesis_lib object -> the name it is documented under."""
    objects = env.get_domain("py").objects
    cache = getattr(env, "_api_documented", None)
    if cache is None or cache[0] != len(objects):
        found = {}
        for name, entry in objects.items():
            if name.startswith("thesis_lib.") and not entry.aliased:
                obj = _import(name)
                if obj is not None and not isinstance(obj, (str, int, float, tuple, frozenset)):
                    found.setdefault(id(obj), name)
        cache = env._api_documented = (len(objects), found)
    return cache[1]


def _missing_reference(app, env, node, contnode):
    target = node.get("reftarget", "")
    if node.get("refdomain") != "py" or not target.startswith("thesis_lib."):
        return None
    obj = _import(target)
    name = _documented(env).get(id(obj)) if obj is not None else None
    if name is None or name == target:
        return None
    return env.get_domain("py").resolve_xref(env, node["refdoc"], app.builder, node["reftype"], name, node, contnode)


def setup(app):
    app.connect("autodoc-process-docstring", _process_docstring)
    app.connect("missing-reference", _missing_reference)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
