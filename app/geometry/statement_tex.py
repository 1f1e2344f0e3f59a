r"""The mathematics of the paper's statements and errata as TeX, for typesetting (KaTeX in the
explorer; any TeX renderer elsewhere).

Pure data keyed by id, so that it does not depend on where the statements are defined:

- ``CLAIM_TEX``: statement id (GET /theorems) -> the claim's formula. The words of the claim
  and how its residual is measured stay in the statement's ``claim``; this is the formula a
  reader would look for in the paper, in the paper's notation.
- ``ERRATUM_TEX``: erratum id (docs/errata.md) -> (printed, corrected), the formula as printed
  and as it should read. Errata about words rather than formulas keep their words in
  ``\text{…}``.
- ``PARAMETER_TEX``: a parameter's domain as written in the catalogs -> the same as TeX.
- ``CONSTANT_TEX``: a constant of the curve responses -> what it is, as TeX.

Conventions as in the paper: Δ is the forward difference (Δp_i = p_{i+1} − p_i, Δ²p_i =
p_{i+1} − 2p_i + p_{i−1}, centred as in (D1)), l_i = |p_i − p_{i−1}|, A_i the signed area
under the edge p_{i−1}p_i.
"""

from __future__ import annotations

_D1 = r"\Delta^2 p_i^y = c\,(l_i + l_{i+1}),\quad c > 0"
_D3 = r"A_i = c\, l_i,\quad c > 0"
_EQ2 = r"\Delta^2 p_i^y = c\,(A_i + A_{i+1}),\quad c > 0"
_C1 = r"c = \frac{4(f_1 - f_0)^3}{(f_0 + f_1)^3} > 0"
_R2 = (
    r"r^* = \frac{3a^3(\lambda-1)^2 - 5a^2b(\lambda-1)\lambda + 2ab^2\lambda^2 - b(\lambda-3)}"
    r"{2\lambda(\lambda-1)(a-b)^2}"
)
_EVEN_Y = (
    r"\frac{(a^{-i/2} - b^{-i/2})\bigl(a^{i/2}b(\lambda-3) + ab^{i/2}(3a(\lambda-1) - 2b\lambda)"
    r"(a(\lambda-1) - b\lambda)\bigr)}{2\lambda(a-b)^2(\lambda-1)}"
)
_P14 = r"\frac{(h-d)^i}{2(h+d)^{i-1}} + \frac{(h+d)^i}{2(h-d)^{i-1}}"
_AB = r"A = (h+d)^{2i} - (h-d)^{2i},\ B = (h-d)^{2i} + (h+d)^{2i}"
_N18 = r"\frac{\bigl(2(h-d)^i(h+d)^i,\ (h+d)^{2i} - (h-d)^{2i}\bigr)}{(h-d)^{2i} + (h+d)^{2i}}"
_N19 = r"\frac{\bigl((h-d)^{2i} - (h+d)^{2i},\ 2(h-d)^i(h+d)^i\bigr)}{(h-d)^{2i} + (h+d)^{2i}}"
_CONVERGENCE = r"\quad\text{as } j \to \infty"
_LEMMA_10 = (
    r"p_i = \Bigl(\sum_{k=0}^{i-1} \frac{s_k - s_{k+1}}{(1 - s_k^2)^{1/2}(1 - s_{k+1}^2)^{1/2}},"
    r"\ (1 - s_i^2)^{-1/2}\Bigr),\quad \sum_{k=0}^{i-1} = -\sum_{k=i}^{-1}\ (i < 0)"
)

#: Statement id -> TeX of its claim.
CLAIM_TEX: dict[str, str] = {
    # Section 3: the conditions (D1), (D3), eq. (2) and the hanging chain
    "d1": _D1,
    "d3": _D3,
    "equation-2": _EQ2,
    "hanging-sticks": r"k_{i+1} - k_i = c\,(l_i + l_{i+1}),\quad k_i = \text{slope of } p_{i-1}p_i",
    "d1-closed-form": (
        r"p_i = \bigl(i\delta,\ C + a\cosh(u_0 + (i - \tfrac12)E)\bigr),\quad "
        r"E = 2\operatorname{artanh} c,\ a = \frac{\delta\sqrt{1 - c^2}}{2c}"
    ),
    "d3-closed-form": (
        r"p_i = \bigl(i\delta,\ a\cosh(v_0 \pm 2iD)\bigr),\quad \tanh D = \frac{\delta}{2c},\ "
        r"a = \sqrt{c^2 - \delta^2/4}"
    ),
    # Section 4.1: (D2a), Theorems 1-3
    "theorem-1": _EQ2 + r",\quad " + _C1 + r"\quad (r = r^*)",
    "theorem-1-start-height": r"r^* = p_0^y = -\frac{f_1(1 + f_0^2)}{2(f_1 - f_0)^2}",
    "theorem-1-gauss-edge": (
        r"\varphi_i - \varphi_{i-1} = -\frac{2(f_{i-1} - f_i)}{(f_{i-1}^2 + 1)(f_i^2 + 1)}"
        r"\,(f_{i-1} + f_i,\ 1 - f_{i-1}f_i)"
    ),
    "theorem-1-gauss-edge-norm": (
        r"\lVert\varphi_i - \varphi_{i-1}\rVert^2 = \frac{4(f_{i-1} - f_i)^2}"
        r"{(f_{i-1}^2 + 1)(f_i^2 + 1)}"
    ),
    "theorem-1-dual-edge": (
        r"p_i - p_{i-1} = -\frac{(f_{i-1} + f_i,\ 1 - f_{i-1}f_i)}{2(f_{i-1} - f_i)}"
    ),
    "theorem-1-x-step": (
        r"p_i^x - p_{i-1}^x = d = \frac{f_{i-1} + f_i}{2(f_i - f_{i-1})}"
        r" = \frac{f_0 + f_1}{2(f_1 - f_0)}"
    ),
    "theorem-1-second-difference": (
        r"p_{i+1} - 2p_i + p_{i-1} = \Bigl(0,\ -\frac{f_i^2 + 1}{2f_i}\Bigr)"
    ),
    "equation-5": r"p_{i-1}^y = -\frac{f_i + f_{i-1}^2 f_i}{2(f_{i-1} - f_i)^2}\quad (r = r^*)",
    "theorem-1-heights": (
        r"p_i^y = -\frac{f_{i-1} + f_{i-1}f_i^2}{2(f_{i-1} - f_i)^2},\quad "
        r"p_{i+1}^y = -\frac{f_{i-1}^2 + f_i^4}{2f_i(f_{i-1} - f_i)^2}"
    ),
    "theorem-1-area-sum": (
        r"A_{i-1} + A_i = \frac{(f_{i-1} + f_i)^3(1 + f_i^2)}{8f_i(f_{i-1} - f_i)^3}"
    ),
    "theorem-2": (
        r"\Delta^2 p_i^y = \begin{cases} c_1 A_i + c_2 A_{i+1} & i \text{ even}\\ "
        r"c_2 A_i + c_1 A_{i+1} & i \text{ odd}\end{cases}\quad (r = r^*)"
    ),
    "theorem-2-start-height": _R2,
    "equation-10": (
        r"\Delta^3 p_i^y = c\,(A_{i+2} - A_i),\quad c = c_1\ (i \text{ even}),\ "
        r"c = c_2\ (i \text{ odd})"
    ),
    "theorem-3-even": (
        r"p_i = \Bigl(\frac{i\bigl(a(\lambda-6)(\lambda-1) - b(\lambda-5)\lambda\bigr)}"
        r"{4\lambda(a-b)(\lambda-1)},\ r + " + _EVEN_Y + r"\Bigr)\quad (i \text{ even})"
    ),
    "theorem-3-odd": r"p_i = \text{(9)}\quad (i \text{ odd})",
    # Section 3 (D2b), Section 5 eq. (17), Section 6: Lemma 10, Theorem 11
    "d2b-mean-curvature": r"H = -\frac{A(f, n)}{A(f)} = 0\quad\text{on every face}",
    "d2b-parallel": r"(p_{i+1} - p_i) \parallel (n_{i+1} - n_i)",
    "equation-17": (
        r"K = \frac{(n_{i+1}^y)^2 - (n_i^y)^2}{(p_{i+1}^y)^2 - (p_i^y)^2},\quad "
        r"H = \frac{p_i^y n_i^y - p_{i+1}^y n_{i+1}^y}{(p_{i+1}^y)^2 - (p_i^y)^2}"
    ),
    "theorem-11-radii": r"p_i^y = \frac{1}{n_i^y} = (1 - s_i^2)^{-1/2}",
    "theorem-11-recursion": (
        r"p_i^x = p_{i-1}^x + \Delta p_{i-1}^y\,\frac{\Delta n_{i-1}^x}{\Delta n_{i-1}^y}"
    ),
    "lemma-10": _LEMMA_10,
    "theorem-11": (
        r"\max_i \bigl\lvert p_i^j - c(i/j)\bigr\rvert \to 0" + _CONVERGENCE + r",\quad "
        r"c(t) = \bigl(-\operatorname{artanh} g(t),\ \cosh\operatorname{artanh} g(t)\bigr)"
    ),
    "example-12": (
        r"n_i^x = s_i = \frac{4i^2}{j^2 + 4i^2} = g(i/j),\quad g(x) = \frac{4x^2}{1 + 4x^2}"
    ),
    "remark-13": r"n_i^x = s_i = \frac{i}{i + j} = g(i/j),\quad g(x) = \frac{x}{1 + x}",
    "remark-13-uniform": (
        r"\int \lvert u'\rvert^3 < \infty,\quad u = \operatorname{artanh} g,\ "
        r"u' = \frac{g'}{1 - g^2}"
    ),
    "lemma-10-proof": (
        r"\sum_{k<i} \frac{g'(t_k)}{1 - g(t_k)^2}(t_k - t_{k+1}),\ "
        r"\sum_{k<i} \frac{s_k - s_{k+1}}{1 - s_k^2} \to \int_0^t \frac{g'}{g^2 - 1},"
        r"\quad t_k = k/j"
    ),
    # Section 3: (D4a)
    "d4a-sticks": r"\lvert d_i - x_i\rvert = h,\quad x_i^y = 0",
    "d4a-arc-length": r"\lvert d_{i+1} - d_i\rvert = s",
    "darboux-d4a": r"\lvert e_{i+1} - e_i\rvert = \lvert x_{i+1} - x_i\rvert",
    "darboux-d4a-distance": r"\lvert x_i - e_i\rvert = 2h - s",
    "rotation-centre-d4a": (
        r"\lvert p_i - x_i\rvert = \lvert p_i - x_{i+1}\rvert,\quad "
        r"\lvert p_i - d_i\rvert = \lvert p_i - d_{i+1}\rvert"
    ),
    "nikolaides-d4a": r"p_i^x = \frac{x_i^x + x_{i+1}^x}{2}",
    "d4a-closed-form": (
        r"\sin\beta_i = \sin\beta_c\, k^{\lvert i - c\rvert},\ k = 1 - \frac{s}{h},\quad "
        r"d_i = x_i + h(\cos\beta_i, \sin\beta_i)"
    ),
    # Section 4.2: (D4b), Theorems 4-6
    "theorem-4-hypothesis": r"d^2 < p_{i-1}^y\, p_i^y",
    "theorem-4-i": _D1,
    "theorem-4-ii": _D3,
    "theorem-4-iii": _EQ2 + r",\quad c = \frac{c_{(D1)}}{c_{(D3)}}",
    "theorem-4-rotation-angle": r"\alpha_i = 2\arctan\frac{d}{p_i^y}",
    "recursion-13": (
        r"p_{i+1}^y = \frac{(p_i^y)^3 + 2d^2 p_i^y + d^2 p_{i-1}^y}{p_i^y p_{i-1}^y - d^2}"
    ),
    "recursion-13-two-step": (
        r"p_{i+2} = \frac{p_i^5 + d^2(p_{i-1}^3 + 2p_{i-1}^2p_i + 3p_{i-1}p_i^2 + 4p_i^3)"
        r" + d^4(2p_{i-1} + 3p_i)}{(d^2 - p_{i-1}p_i)^2}\quad (p = p^y)"
    ),
    "theorem-5": r"p_i = \Bigl((2i - 1)d,\ " + _P14 + r"\Bigr)",
    "theorem-6": r"d_i = \text{(16)}",
    "darboux-d4b": r"\lvert e_{i+1} - e_i\rvert = \lvert x_{i+1} - x_i\rvert = 2d",
    "darboux-d4b-distance": r"\lvert x_i - e_i\rvert = 2h",
    "nikolaides-d4b": (r"\angle x_i d_i p_i = \angle x_i d_i p_{i+1} = \frac{\pi}{2}"),
    # Section 5: curvature, Gauss images, Theorems 7 and 8
    "equation-18": r"n_i = " + _N18,
    "equation-18-slope": (
        r"n_i = \frac{(1, k_{i+1})}{\sqrt{1 + k_{i+1}^2}},\quad "
        r"k_{i+1} = \frac{p_{i+1}^y - p_i^y}{2d}"
    ),
    "equation-19": r"\tilde n_i = " + _N19,
    "equation-19-rotation": r"\tilde n_i = (-n_i^y,\ n_i^x)",
    "equation-20-inversion": (
        r"m_i = \frac{2(\tilde n_{i-1} + \tilde n_i)}{\lvert\tilde n_{i-1} + \tilde n_i\rvert^2}"
    ),
    "equation-20": (r"m_i = \frac{\bigl(dB - hA,\ 2h(h^2 - d^2)^i\bigr)}{hB - dA},\quad " + _AB),
    "theorem-7": r"K = \frac{A(n)}{A(f)} = -\frac{1}{h^2}\quad\text{on every face}",
    "theorem-8": r"H = -\frac{A(f, m)}{A(f)} = 0\quad\text{on every face}",
    # Section 5 on surface meshes: planarity, parallelity, vanishing mean curvature
    "face-planarity": r"f_{k,j},\ f_{k,j+1},\ f_{k+1,j+1},\ f_{k+1,j}\ \text{lie in one plane}",
    "face-parallelity": r"\vec A(f) \times \vec A(n) = 0\quad\text{on every face}",
    "vanishing-mean-curvature": r"H = -\frac{A(f, n)}{A(f)} = 0\quad\text{on every face}",
    # Section 6: Theorems 14 and 15
    "theorem-14": (
        r"c(x) \to \bigl(x,\ h\cosh(x/h)\bigr)\quad\text{as } d \to 0,\quad "
        r"c\bigl((2i - 1)d\bigr) = p_i"
    ),
    "theorem-14-interpolation": r"c\bigl((2i - 1)d\bigr) = p_i",
    "theorem-14-rearrangement": (
        r"c^y(x) = \frac{h(1 - d/h)^{\frac{x+d}{2d}}}{2(1 + d/h)^{\frac{x-d}{2d}}}"
        r" + \frac{h(1 + d/h)^{\frac{x+d}{2d}}}{2(1 - d/h)^{\frac{x-d}{2d}}}"
    ),
    "equation-21-substitution": (
        r"\Bigl(1 - \frac{d}{h}\Bigr)^{\frac{x+d}{2d}} = \Bigl(1 - \frac{x}{hD}\Bigr)^{D/2}"
        r"\Bigl(1 - \frac{x}{hD}\Bigr)^{1/2},\quad d = \frac{x}{D}"
    ),
    "equation-21": r"\Bigl(1 - \frac{d}{h}\Bigr)^{\frac{x+d}{2d}} \to e^{-x/(2h)}\quad (d \to 0)",
    "theorem-15": (
        r"c(x) \to \Bigl(x - h\tanh\frac{x}{h},\ \frac{h}{\cosh(x/h)}\Bigr)"
        r"\quad\text{as } d \to 0,\ \text{uniformly on } \mathbb{R}"
    ),
    "theorem-15-interpolation": r"c\bigl((2i - 1)d\bigr) = d_i",
    "theorem-15-proof-y": (
        r"\frac{2h}{f(d) + g(d)} = c^y(x),\quad "
        r"f(d) = \Bigl(\frac{1 - d/h}{1 + d/h}\Bigr)^{\frac{x+d}{2d}},\ g(d) = \frac{1}{f(d)}"
    ),
    "theorem-15-proof-x": (
        r"\frac{g(d) - f(d)}{g(d) + f(d)} = \frac{x + d - c^x(x)}{h},\quad "
        r"f(d) = (1 - d/h)^{\frac{x+d}{d}},\ g(d) = (1 + d/h)^{\frac{x+d}{d}}"
    ),
    "inequality-22": (
        r"\frac{1}{f(d) + g(d)} \to \frac{1}{f + g},\quad "
        r"\frac{f(d) - g(d)}{f(d) + g(d)} \to \frac{f - g}{f + g}"
    ),
    # Section 2: the smooth tractrix (S4)
    "tractrix-s4": r"\bigl\lvert d(x) - (x, 0)\bigr\rvert = h,\quad d'(x) \parallel (x, 0) - d(x)",
    "evolute-s4": (
        r"q(x) = d + \frac{\lvert d'\rvert^2}{d' \times d''}\,J d' = \bigl(x,\ h\cosh(x/h)\bigr)"
    ),
    "nikolaides-s4": r"\angle\bigl((x, 0),\ d(x),\ q(x)\bigr) = \frac{\pi}{2}",
}

#: Erratum id (docs/errata.md) -> (TeX as printed, TeX as corrected).
ERRATUM_TEX: dict[str, tuple[str, str]] = {
    "E1": (
        r"\alpha_i = \angle\bigl((x_i, 0),\ p_i,\ (x_{i+1}, 0)\bigr)",
        r"\alpha_i = \angle\bigl(x_{i-1},\ p_i,\ x_i\bigr),\quad p_i^x = (2i - 1)d",
    ),
    "E2": (
        r"\frac{\Delta^2 p_i^{y2}}{l_i + l_{i+1}} = "
        r"\frac{\Delta^2 p_{i+1}^{y2}}{l_{i+1} + l_{i+2}},"
        r"\quad l_i = \sqrt{4d^2 + (p_i^y - p_{i-1}^y)^2}",
        r"\frac{\Delta^2 p_i^y}{l_i + l_{i+1}} = \frac{\Delta^2 p_{i+1}^y}{l_{i+1} + l_{i+2}},"
        r"\quad l_i = \lvert p_{i+1} - p_i\rvert",
    ),
    "E3": (
        r"d^4\bigl(2(p_i^y)^3 + 2p_{i-1}^y + 3p_i^y\bigr)",
        r"d^4\bigl(2p_{i-1}^y + 3p_i^y\bigr)",
    ),
    "E20": (
        r"d_i \in \text{stick } i - 1\ \text{for all } i \in \mathbb{Z}",
        r"d_i \in \text{stick } i - 1\ (i > c),\quad d_i \in \text{stick } i + 1\ (i < c)",
    ),
    "E21": (
        r"e_i = \text{reflection of } x_i \text{ in } \tfrac12(d_i + d_{i+1})",
        r"e_i = \text{reflection of } x_i \text{ in } \tfrac12(d_i + d_{i+1})\ (i \ge c),\ "
        r"\tfrac12(d_{i-1} + d_i)\ (i < c)",
    ),
    "E40": (
        r"(\Delta p_{i-1+j})^x = \frac{f_{i-1+j} + f_{i+j}}{2(f_{i-1+j} - f_{i+j})}",
        r"(\Delta p_{i-1+j})^x = \frac{f_{i-1+j} + f_{i+j}}{2(f_{i+j} - f_{i-1+j})} = d > 0",
    ),
    "E41": (
        r"\Delta^2 p_{i-1} = \Bigl(0,\ \frac{f_i^2 + 1}{2f_i}\Bigr)",
        r"\Delta^2 p_{i-1} = \Bigl(0,\ -\frac{f_i^2 + 1}{2f_i}\Bigr)",
    ),
    "E42": (
        r"c = \frac{4(f_{i-1} - f_i)^3}{(f_{i-1} + f_i)^3}",
        r"c = \frac{4(f_i - f_{i-1})^3}{(f_{i-1} + f_i)^3} = " + _C1[4:],
    ),
    "E43": (
        r"p_i^y = \frac{(b^{-i/2} - a^{-i/2})(\ldots)}{2\lambda(a-b)^2(\lambda-1)} + r",
        r"p_i^y = \frac{(a^{-i/2} - b^{-i/2})(\ldots)}{2\lambda(a-b)^2(\lambda-1)} + r",
    ),
    "E44": (
        r"r = \frac{3a^3(\lambda-1)^2 - 5a^2b(\lambda-1)\lambda + 2ab^2\lambda^2 - b(\lambda-3)}"
        r"{\bigl[2\lambda(\lambda-1)a - b\bigr]^2}",
        _R2,
    ),
    "E45": (
        r"\text{(D2a) hexagons satisfy (2)}",
        r"\text{(D2a) hexagons satisfy (7) with } c_1 \ne c_2\text{, not (2)}",
    ),
    "E60": (
        r"n_i = \frac{\bigl(2(h-d)^i(h+d)^i,\ (h-d)^{2i} - (h+d)^{2i}\bigr)}"
        r"{(h-d)^{2i} + (h+d)^{2i}}",
        r"n_i = " + _N18 + r" = (\operatorname{sech} iL,\ \tanh iL)",
    ),
    "E61": (
        r"n_i = \Bigl(\sqrt{\frac{1}{1 + k_{i+1}^2}},\ "
        r"\sqrt{\frac{k_{i+1}^2}{1 + k_{i+1}^2}}\Bigr)",
        r"n_i = \frac{(1, k_{i+1})}{\sqrt{1 + k_{i+1}^2}}",
    ),
    "E62": (
        r"\tilde n_i = \frac{\bigl((h+d)^{2i} - (h-d)^{2i},\ 2(h-d)^i(h+d)^i\bigr)}"
        r"{(h-d)^{2i} + (h+d)^{2i}}",
        r"\tilde n_i = " + _N19 + r" = (-\tanh iL,\ \operatorname{sech} iL)",
    ),
    "E63": (
        r"m_i = \frac{\bigl(hA - dB,\ 2h(h^2 - d^2)^i\bigr)}{dA + hB}",
        r"m_i = \frac{\bigl(dB - hA,\ 2h(h^2 - d^2)^i\bigr)}{hB - dA}"
        r" = \Bigl(-\tanh\bigl((i - \tfrac12)L\bigr),\ \frac{h}{p_i^y}\Bigr)",
    ),
    "E64": (
        r"\sum_{k=0}^{i-1}\ (i < 1):\ k = i - 1, \ldots, 0",
        r"\sum_{k=0}^{i-1} = -\sum_{k=i}^{-1}\ (i < 0),\quad 0\ (i = 0)",
    ),
    "E65": (
        r"\sum_{k=0}^{i-1} \frac{g'(s_k^j)}{1 - g(s_k^j)^2}(s_k^j - s_{k+1}^j)",
        r"\sum_{k=0}^{i-1} \frac{g'(t_k)}{1 - g(t_k)^2}(t_k - t_{k+1}),\quad t_k = \frac{k}{j}",
    ),
    "E66": (
        r"g' \text{ bounded} \Rightarrow p^j \to C \text{ uniformly}",
        r"\int \lvert u'\rvert^3 < \infty,\ u = \operatorname{artanh} g \Rightarrow "
        r"\text{uniform } (s_i = \tfrac{i}{i+j}\text{: on } t \ge t_0 > -\tfrac12)",
    ),
    "E80": (
        r"f(d) = \frac{1 - d/h}{1 + d/h},\quad g(d) = \frac{1}{f(d)}",
        r"f(d) = \Bigl(\frac{1 - d/h}{1 + d/h}\Bigr)^{\frac{x+d}{2d}},\quad g(d) = \frac{1}{f(d)}",
    ),
    "E81": (
        r"f(d) = 1 - \frac{d}{h},\quad g(d) = 1 + \frac{d}{h}",
        r"f(d) = \Bigl(1 - \frac{d}{h}\Bigr)^{\frac{x+d}{d}},\quad "
        r"g(d) = \Bigl(1 + \frac{d}{h}\Bigr)^{\frac{x+d}{d}}",
    ),
}

#: A parameter's domain as the catalogs write it (``ParameterInfo.domain``) -> the same as TeX,
#: for the explorer's parameter help. Keyed by the domain text, not the name: ``c``, ``delta``
#: and ``s`` mean different things in different discretizations.
PARAMETER_TEX: dict[str, str] = {
    "0 < c < 1": r"0 < c < 1",
    "c > 0": r"c > 0",
    "delta > 0": r"\delta > 0",
    "0 < delta < 2c": r"0 < \delta < 2c",
    "y0 >= √(c² − delta²/4)": r"y_0 \ge \sqrt{c^2 - \delta^2/4}",
    "0 < f0 < f1": r"0 < f_0 < f_1",
    "any real; Theorem 1 holds only at r*": (
        r"r \in \mathbb{R};\ \text{Theorem 1 holds only at } r^*"
    ),
    "any real; Theorem 2 holds only at r*": (
        r"r \in \mathbb{R};\ \text{Theorem 2 holds only at } r^*"
    ),
    "0 < a < b": r"0 < a < b",
    "0 < lambda < 1": r"0 < \lambda < 1",
    "j >= 1": r"j \ge 1",
    "strictly increasing, |s_i| < 1, s_0 = 0": r"s_i < s_{i+1},\ \lvert s_i\rvert < 1,\ s_0 = 0",
    "h > 0": r"h > 0",
    "0 < s < h": r"0 < s < h",
    "0 < beta0 < π": r"0 < \beta_0 < \pi",
    "0 < d < h": r"0 < d < h",
    "any real number (float64: |y1 − y0|/delta <= 1e150)": (
        r"y_1 \in \mathbb{R}\ (\text{float64: } \lvert y_1 - y_0\rvert/\delta \le 10^{150})"
    ),
    "i_min <= i_max": r"i_{\min} \le i_{\max}",
    "i_min >= 0 (example-12), i_min > −j/2 (remark-13)": (
        r"i_{\min} \ge 0\ (\text{example-12}),\ i_{\min} > -j/2\ (\text{remark-13})"
    ),
}

#: A fitted or derived constant of the curve responses (``constants``) -> what it is, as TeX.
CONSTANT_TEX: dict[str, str] = {
    "d1": r"c \text{ of (D1)}:\ \Delta^2 p_i^y = c\,(l_i + l_{i+1})",
    "d3": r"c \text{ of (D3)}:\ A_i = c\, l_i",
    "eq2": r"c \text{ of (2)}:\ \Delta^2 p_i^y = c\,(A_i + A_{i+1})",
    "equilibrium": r"c:\ k_{i+1} - k_i = c\,(l_i + l_{i+1})",
    "c_theorem_1": _C1,
    "r_theorem_1": r"r^* = -\frac{f_1(1 + f_0^2)}{2(f_1 - f_0)^2}",
    "x_step": r"d = \frac{f_0 + f_1}{2(f_1 - f_0)}",
    "c1": r"c_1 \text{ of (7)}",
    "c2": r"c_2 \text{ of (7)}",
    "c1_eq11": r"c_1 \text{ of (11)}",
    "c2_eq11": r"c_2 \text{ of (11)}",
    "r_theorem_2": r"r^* \text{ of Theorem 2}",
    "x_step_even": r"p_{i+1}^x - p_i^x\ (i \text{ even})",
    "x_step_odd": r"p_{i+1}^x - p_i^x\ (i \text{ odd})",
}
