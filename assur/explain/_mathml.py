r"""The small subset of TeX the note writes, turned into MathML (no network needed).

Supported: numbers, letters, operators, groups ``{...}``, sub- and superscripts,
``\frac``, ``\sqrt``, ``\vec``, ``\dot``, ``\ddot``, ``\mathrm``, ``\text``,
``\left``/``\right``, Greek letters, the operators and spaces of :data:`SYMBOLS`.
As in TeX, ``\text`` keeps its spaces while ``\mathrm`` stays mathematics: its
spaces come from ``\,`` or ``\ `` and its ``^2`` is a superscript. Anything else
raises ``ValueError`` (a test renders every note, so a construct missing here shows
at once). Browsers render MathML Core natively.
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
FUNCTIONS = ("arccos", "arcsin", "arctan", "cos", "cot", "sin", "tan", "ln", "exp")
SPACES = {"quad": "1em", "qquad": "2em", ",": "0.17em", ";": "0.28em", " ": "0.25em"}
TEXT_SPACES = {
    "quad": "\u2003", "qquad": "\u2003\u2003", ",": "\u2009", ";": "\u2005", " ": " ",
}  # fmt: skip
"""The spaces of :data:`SPACES` as characters (em, thin and four-per-em spaces), for
inside ``\\text`` and ``\\mathrm``, where they join the words of one ``<mtext>``."""
FENCES = frozenset("()[]|")
"""Brackets and bars: set at their own size unless after ``\\left`` or ``\\right``."""
BAR = '<mo stretchy="false">|</mo>'
SIGN_AFTER = frozenset("([{=,:;+−⋅×±∓≈≤≥≠∑")
"""Operators after which a minus is a number's sign, not a subtraction: set as a
prefix, with no space between it and the number (MathML spaces an infix minus on
both sides: ``( - 2960, 0)``)."""
TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\d+(?:\.\d+)?|[A-Za-z]|\s+|.", re.S)
EDGE_SPACES = re.compile(r"^ +| +$")


def mathml(tex: str, display: bool = False) -> str:
    r"""Return ``tex`` as a ``<math>`` element (block when ``display``).

    Examples
    --------
    >>> mathml(r"\omega_{1} = 200")
    '<math><msub><mi>ω</mi><mrow><mn>1</mn></mrow></msub><mo>=</mo><mn>200</mn></math>'
    """
    # spaces are kept as tokens: math skips them, but \text sets them
    tokens = TOKEN.findall(tex)
    body, rest = _sequence(tokens, 0, None)
    if rest != len(tokens):
        msg = f"unbalanced braces in {tex!r}"
        raise ValueError(msg)
    block = ' display="block"' if display else ""
    return f"<math{block}>{body}</math>"


def _skip(tokens: list[str], i: int) -> int:
    """Return the index of the first token from ``i`` on that is not a space."""
    while i < len(tokens) and tokens[i].isspace():
        i += 1
    return i


def _sequence(tokens: list[str], i: int, end: str | None) -> tuple[str, int]:
    """Parse atoms until ``end`` (a closing brace) or the end; return MathML."""
    out: list[str] = []
    bars = 0
    i = _skip(tokens, i)
    while i < len(tokens) and tokens[i] != end:
        if tokens[i] == "-":
            # the minus sign, not the hyphen; a sign at the start or after an
            # operator hugs its number
            before = [a for a in out if not a.startswith("<mspace")]
            # after words (\text{read at } -0.01 m) a minus is a sign too
            sign = (
                not before
                or _operator(before[-1]) in SIGN_AFTER
                or before[-1].startswith("<mtext>")
            )
            out.append('<mo form="prefix">−</mo>' if sign else "<mo>−</mo>")
            i = _skip(tokens, i + 1)
            continue
        atom, i = _atom(tokens, i)
        if atom.startswith(BAR) or atom[atom.find(">") + 1 :].startswith(BAR):
            # |x| is a pair of fences, not two infix bars spaced on both sides
            form = "postfix" if bars % 2 else "prefix"
            atom = atom.replace(BAR, BAR.replace("<mo", f'<mo form="{form}"'), 1)
            bars += 1
        out.append(atom)
        i = _skip(tokens, i)
    if end is not None:
        if i >= len(tokens):
            msg = "a brace is not closed"
            raise ValueError(msg)
        i += 1
    return "".join(out), i


def _operator(atom: str) -> str:
    """Return the operator an atom is (``<mo>=</mo>`` gives ``=``), else ""."""
    found = re.fullmatch(r"<mo(?: [^>]*)?>([^<]*)</mo>", atom)
    return found.group(1) if found else ""


def _argument(tokens: list[str], i: int) -> tuple[str, int]:
    """Parse one argument: a group in braces, or a single token."""
    i = _skip(tokens, i)
    if i >= len(tokens):
        msg = "an argument is missing"
        raise ValueError(msg)
    if tokens[i] == "{":
        body, i = _sequence(tokens, i + 1, "}")
        return f"<mrow>{body}</mrow>", i
    return _base(tokens, i)


def _mtext(text: str) -> str:
    """Return ``text`` as ``<mtext>``, its edge spaces made no-break spaces."""
    # a browser drops the spaces at the ends of a MathML token (``at `` shows ``at``)
    kept = EDGE_SPACES.sub(lambda m: "\u00a0" * len(m.group()), text)
    return f"<mtext>{escape(kept)}</mtext>"


def _character(token: str) -> str:
    r"""Return the text a token of ``\text`` or ``\mathrm`` stands for."""
    if not token.startswith("\\"):
        return token
    name = token[1:]
    # a name's caret is written \hat{} (over nothing); its braces are skipped
    for table in (TEXT_SPACES, SYMBOLS, GREEK, {"hat": "^"}):
        if name in table:
            return table[name]
    msg = f"the note's MathML knows no \\{name} in text"
    raise ValueError(msg)


def _group_end(tokens: list[str], i: int) -> int:
    """Return the index of the brace that closes the one before ``i``."""
    depth = 1
    while depth:
        if i >= len(tokens):
            msg = "a brace is not closed"
            raise ValueError(msg)
        depth += tokens[i] == "{"
        depth -= tokens[i] == "}"
        i += 1
    return i - 1


def _text(tokens: list[str], i: int) -> tuple[str, int]:
    r"""Parse the argument of ``\text``: words set as written, spaces and all."""
    i = _skip(tokens, i)
    if i >= len(tokens):
        msg = "an argument is missing"
        raise ValueError(msg)
    if tokens[i] != "{":
        return _mtext(_character(tokens[i])), i + 1
    end = _group_end(tokens, i + 1)
    chars, after_word = [], False
    for t in tokens[i + 1 : end]:
        # TeX drops the spaces after a control word (\quad x), and inner braces
        if t in ("{", "}") or (after_word and t.isspace()):
            continue
        chars.append(" " if t.isspace() else _character(t))
        after_word = t[0] == "\\" and t[1:].isalpha()
    return _mtext("".join(chars)), end + 1


def _roman(tokens: list[str], i: int) -> tuple[str, int]:
    r"""Parse the argument of ``\mathrm``: upright text whose ``^``/``_`` are scripts.

    It stays mathematics: spaces between letters are not set (``\,`` is), and
    ``\mathrm{m/s^2}`` raises the 2 over the s alone, as TeX does.
    """
    i = _skip(tokens, i)
    if i >= len(tokens) or tokens[i] != "{":
        return _text(tokens, i)
    end = _group_end(tokens, i + 1)
    pieces, run, j = [], "", i + 1
    while j < end:
        t = tokens[j]
        if t in ("^", "_"):
            # a script binds to the character before it, not to the whole word
            if run[:-1]:
                pieces.append(_mtext(run[:-1]))
            script, j = _scripts(_mtext(run[-1:]), tokens, j)
            if j > end:
                msg = "a script in \\mathrm is missing its argument"
                raise ValueError(msg)
            pieces.append(script)
            run = ""
            continue
        if t not in ("{", "}") and not t.isspace():
            run += _character(t)
        j += 1
    if run:
        pieces.append(_mtext(run))
    body = "".join(pieces)
    return (body if len(pieces) == 1 else f"<mrow>{body}</mrow>"), end + 1


def _atom(tokens: list[str], i: int) -> tuple[str, int]:
    """Parse a base with its sub- and superscripts."""
    base, i = _base(tokens, i)
    return _scripts(base, tokens, i)


def _scripts(base: str, tokens: list[str], i: int) -> tuple[str, int]:
    """Attach the sub- and superscripts from ``i`` on to ``base``."""
    sub = sup = None
    i = _skip(tokens, i)
    while i < len(tokens) and tokens[i] in ("_", "^"):
        arg, j = _argument(tokens, i + 1)
        if tokens[i] == "_":
            sub = arg
        else:
            sup = arg
        i = _skip(tokens, j)
    if sub and sup:
        return f"<msubsup>{base}{sub}{sup}</msubsup>", i
    if sub:
        return f"<msub>{base}{sub}</msub>", i
    if sup:
        return f"<msup>{base}{sup}</msup>", i
    return base, i


def _base(tokens: list[str], i: int) -> tuple[str, int]:
    """Parse one token (or a command with its arguments)."""
    i = _skip(tokens, i)
    if i >= len(tokens):
        msg = "an argument is missing"
        raise ValueError(msg)
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
    if t in FENCES:
        # TeX grows a bracket only after \left or \right: a plain one keeps its
        # size (a stretched ")" under a square drooped below its line)
        return f'<mo stretchy="false">{t}</mo>', i + 1
    return f"<mo>{escape(t)}</mo>", i + 1


def _command(name: str, tokens: list[str], i: int) -> tuple[str, int]:
    """Parse a command; ``i`` is past it."""
    if name in GREEK:
        return f"<mi>{GREEK[name]}</mi>", i
    if name in SPACES:
        return f'<mspace width="{SPACES[name]}"/>', i
    if name in SYMBOLS and SYMBOLS[name] in FENCES:
        return f'<mo stretchy="false">{SYMBOLS[name]}</mo>', i
    if name in SYMBOLS:
        return f"<mo>{escape(SYMBOLS[name])}</mo>", i
    if name in FUNCTIONS:
        # a thin space after the name, as TeX sets it: "tan 38.79", not "tan38.79"
        return f'<mi>{name}</mi><mspace width="{SPACES[","]}"/>', i
    if name == "text":
        return _text(tokens, i)
    if name == "mathrm":
        return _roman(tokens, i)
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
        # a dot set as an accent is drawn too small to see over an s at text
        # size in Chromium: as an over-script it shows
        accent = "" if name in ("dot", "ddot") else ' accent="true"'
        return f"<mover{accent}>{arg}<mo>{mark}</mo></mover>", i
    if name in ("left", "right"):
        fence, i = _base(tokens, i)
        return fence.replace(' stretchy="false"', ""), i
    msg = f"the note's MathML knows no \\{name}"
    raise ValueError(msg)
