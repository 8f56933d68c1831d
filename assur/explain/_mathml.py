r"""The small subset of TeX the note writes, turned into MathML (no network needed).

Supported: numbers, letters, operators, groups ``{...}``, sub- and superscripts,
``\frac``, ``\sqrt``, ``\vec``, ``\dot``, ``\ddot``, ``\mathrm``, ``\text``,
``\left``/``\right``, Greek letters, the operators and spaces of :data:`SYMBOLS`.
Anything else raises ``ValueError`` (a test renders every note, so a construct
missing here shows at once). Browsers render MathML Core natively.
"""

from __future__ import annotations

import re
from html import escape

__all__ = ["mathml"]

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "varepsilon": "ε",
    "epsilon": "ϵ", "eta": "η", "theta": "θ", "lambda": "λ", "mu": "μ", "nu": "ν",
    "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "varphi": "φ", "phi": "ϕ",
    "psi": "ψ", "omega": "ω", "Delta": "Δ", "Sigma": "Σ", "Omega": "Ω",
}  # fmt: skip
SYMBOLS = {
    "cdot": "⋅", "times": "×", "pm": "±", "mp": "∓", "perp": "⊥", "parallel": "∥",
    "sum": "∑", "approx": "≈", "to": "→", "le": "≤", "ge": "≥", "neq": "≠",
    "circ": "°", "sim": "∼", "backslash": "\\", "vert": "|", "%": "%", "_": "_",
    "{": "{", "}": "}", "$": "$", "&": "&", "#": "#",
}  # fmt: skip
FUNCTIONS = ("arccos", "arcsin", "arctan", "cos", "sin", "tan", "ln", "exp")
SPACES = {"quad": "1em", "qquad": "2em", ",": "0.17em", ";": "0.28em", " ": "0.25em"}
TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\d+(?:\.\d+)?|[A-Za-z]|\s+|.", re.S)


def mathml(tex: str, display: bool = False) -> str:
    r"""Return ``tex`` as a ``<math>`` element (block when ``display``).

    Examples
    --------
    >>> mathml(r"\omega_{1} = 200")
    '<math><msub><mi>ω</mi><mrow><mn>1</mn></mrow></msub><mo>=</mo><mn>200</mn></math>'
    """
    tokens = [t for t in TOKEN.findall(tex) if not t.isspace()]
    body, rest = _sequence(tokens, 0, None)
    if rest != len(tokens):
        msg = f"unbalanced braces in {tex!r}"
        raise ValueError(msg)
    block = ' display="block"' if display else ""
    return f"<math{block}>{body}</math>"


def _sequence(tokens: list[str], i: int, end: str | None) -> tuple[str, int]:
    """Parse atoms until ``end`` (a closing brace) or the end; return MathML."""
    out = []
    while i < len(tokens) and tokens[i] != end:
        atom, i = _atom(tokens, i)
        out.append(atom)
    if end is not None:
        if i >= len(tokens):
            msg = "a brace is not closed"
            raise ValueError(msg)
        i += 1
    return "".join(out), i


def _argument(tokens: list[str], i: int) -> tuple[str, int]:
    """Parse one argument: a group in braces, or a single token."""
    if i >= len(tokens):
        msg = "an argument is missing"
        raise ValueError(msg)
    if tokens[i] == "{":
        body, i = _sequence(tokens, i + 1, "}")
        return f"<mrow>{body}</mrow>", i
    return _base(tokens, i)


def _raw(tokens: list[str], i: int) -> tuple[str, int]:
    r"""Return the text of a braced argument as written (for ``\text``)."""
    if tokens[i] != "{":
        return tokens[i], i + 1
    depth, j, parts = 1, i + 1, []
    while depth:
        t = tokens[j]
        depth += t == "{"
        depth -= t == "}"
        if depth:
            parts.append(SYMBOLS.get(t[1:], t[1:]) if t.startswith("\\") else t)
        j += 1
    return "".join(parts), j


def _atom(tokens: list[str], i: int) -> tuple[str, int]:
    """Parse a base with its sub- and superscripts."""
    base, i = _base(tokens, i)
    sub = sup = None
    while i < len(tokens) and tokens[i] in ("_", "^"):
        arg, j = _argument(tokens, i + 1)
        if tokens[i] == "_":
            sub = arg
        else:
            sup = arg
        i = j
    if sub and sup:
        return f"<msubsup>{base}{sub}{sup}</msubsup>", i
    if sub:
        return f"<msub>{base}{sub}</msub>", i
    if sup:
        return f"<msup>{base}{sup}</msup>", i
    return base, i


def _base(tokens: list[str], i: int) -> tuple[str, int]:
    """Parse one token (or a command with its arguments)."""
    t = tokens[i]
    if t == "{":
        body, i = _sequence(tokens, i + 1, "}")
        return f"<mrow>{body}</mrow>", i
    if t[0].isdigit():
        return f"<mn>{t}</mn>", i + 1
    if t.isalpha():
        return f"<mi>{t}</mi>", i + 1
    if t.startswith("\\"):
        return _command(t[1:], tokens, i + 1)
    return f"<mo>{escape(t)}</mo>", i + 1


def _command(name: str, tokens: list[str], i: int) -> tuple[str, int]:
    """Parse a command; ``i`` is past it."""
    if name in GREEK:
        return f"<mi>{GREEK[name]}</mi>", i
    if name in SPACES:
        return f'<mspace width="{SPACES[name]}"/>', i
    if name in SYMBOLS:
        return f"<mo>{escape(SYMBOLS[name])}</mo>", i
    if name in FUNCTIONS:
        return f"<mi>{name}</mi>", i
    if name in ("mathrm", "text"):
        text, i = _raw(tokens, i)
        return f"<mtext>{escape(text)}</mtext>", i
    if name == "frac":
        top, i = _argument(tokens, i)
        bottom, i = _argument(tokens, i)
        return f"<mfrac>{top}{bottom}</mfrac>", i
    if name == "sqrt":
        arg, i = _argument(tokens, i)
        return f"<msqrt>{arg}</msqrt>", i
    if name in ("vec", "dot", "ddot", "hat"):
        arg, i = _argument(tokens, i)
        mark = {"vec": "→", "dot": "˙", "ddot": "¨", "hat": "^"}[name]
        return f'<mover accent="true">{arg}<mo>{mark}</mo></mover>', i
    if name in ("left", "right"):
        return _base(tokens, i)
    msg = f"the note's MathML knows no \\{name}"
    raise ValueError(msg)
