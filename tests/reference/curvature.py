"""Independent high-precision Section 5 and (D2b): plain mpmath, no code shared with app.

Different algorithms on purpose:
- areas by Newell's formula (sum of v_k × v_{k+1} over the polygon), the mixed area by
  polarization, A(f, n) = (A(f + n) − A(f − n))/4, and faces rotated with mpmath matrices;
- the inscribed Gauss image n by intersecting the line through n_i along the tractrix edge with
  the unit circle (the second root of a quadratic);
- the contact points by normalizing the edge turned by 90°, m by solving the two tangent
  equations m·ñ_{i−1} = 1, m·ñ_i = 1 with ``lu_solve``;
- (D2b) by searching, along the line through p_i parallel to the Gauss image edge, the point
  where the mixed area vanishes (``findroot``).
"""

from __future__ import annotations

import mpmath


def context(dps: int = 60) -> mpmath.MPContext:
    ctx = mpmath.MPContext()
    ctx.dps = dps
    return ctx


def rotate(ctx, point, angle):
    """R_angle (x, y, 0) about the x-axis, as an mpmath column."""
    rotation = ctx.matrix(
        [[1, 0, 0], [0, ctx.cos(angle), -ctx.sin(angle)], [0, ctx.sin(angle), ctx.cos(angle)]]
    )
    return rotation * ctx.matrix([point[0], point[1], 0])


def face(ctx, a, b, angle):
    """The quad (a, 0), (a, θ), (b, θ), (b, 0) of meridian points a, b."""
    zero = ctx.mpf(0)
    return [
        rotate(ctx, a, zero),
        rotate(ctx, a, angle),
        rotate(ctx, b, angle),
        rotate(ctx, b, zero),
    ]


def _cross(ctx, u, v):
    return ctx.matrix(
        [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    )


def newell(ctx, polygon):
    """Vector area ½ Σ v_k × v_{k+1}."""
    total = ctx.matrix([0, 0, 0])
    for k in range(len(polygon)):
        total += _cross(ctx, polygon[k], polygon[(k + 1) % len(polygon)])
    return total / 2


def curvatures(ctx, f, n):
    """(K, H) = (A(n)/A(f), −A(f,n)/A(f)) along f's normal, by Newell and polarization."""
    area_f = newell(ctx, f)
    unit = area_f / ctx.norm(area_f)
    a_f = ctx.norm(area_f)
    a_n = ctx.fdot(newell(ctx, n), unit)
    plus = newell(ctx, [x + y for x, y in zip(f, n, strict=True)])
    minus = newell(ctx, [x - y for x, y in zip(f, n, strict=True)])
    a_fn = ctx.fdot((plus - minus) / 4, unit)
    return a_n / a_f, -a_fn / a_f


def inscribed(ctx, polygon: dict, start_index: int, start_point):
    """Inscribed polygon with edges parallel to ``polygon`` (dict i -> (x, y)) through start."""
    out = {start_index: start_point}

    def second_intersection(point, direction):
        # |point + t·direction|² = 1 has the roots 0 and t = −2 point·direction / |direction|²
        px, py = point
        dx, dy = direction
        a = dx * dx + dy * dy
        b = 2 * (px * dx + py * dy)
        c = px * px + py * py - 1
        roots = ctx.polyroots([c, b, a], asc=True)
        t = max(roots, key=lambda r: abs(r))
        t = ctx.re(t)
        return (px + t * dx, py + t * dy)

    keys = sorted(polygon)
    for i in range(start_index, keys[-1]):
        e = (polygon[i + 1][0] - polygon[i][0], polygon[i + 1][1] - polygon[i][1])
        out[i + 1] = second_intersection(out[i], e)
    for i in range(start_index, keys[0], -1):
        e = (polygon[i][0] - polygon[i - 1][0], polygon[i][1] - polygon[i - 1][1])
        out[i - 1] = second_intersection(out[i], e)
    return out


def contact_points(ctx, polygon: dict):
    """ñ_i for the edges i, i+1 of a meridian running towards +x: (−e_y, e_x)/|e|."""
    out = {}
    for i in sorted(polygon)[:-1]:
        ex, ey = polygon[i + 1][0] - polygon[i][0], polygon[i + 1][1] - polygon[i][1]
        length = ctx.sqrt(ex * ex + ey * ey)
        out[i] = (-ey / length, ex / length)
    return out


def circumscribed(ctx, contacts: dict):
    """m_i solving m·ñ_{i−1} = 1 and m·ñ_i = 1."""
    out = {}
    for i in sorted(contacts)[1:]:
        a, b = contacts[i - 1], contacts[i]
        solution = ctx.lu_solve(ctx.matrix([[a[0], a[1]], [b[0], b[1]]]), ctx.matrix([1, 1]))
        out[i] = (solution[0], solution[1])
    return out


def d2b(ctx, s: dict):
    """(D2b) meridian for a sequence s (dict i -> s_i containing 0): dict i -> (x, y)."""
    n = {i: (v, ctx.sqrt(1 - v * v)) for i, v in s.items()}
    angle = ctx.pi / 3
    p = {0: (ctx.mpf(0), ctx.mpf(1))}

    def solve(known, k_from, k_to):
        e = (n[k_to][0] - n[k_from][0], n[k_to][1] - n[k_from][1])

        def mixed(mu):
            other = (known[0] + mu * e[0], known[1] + mu * e[1])
            a, b = (known, other) if k_to > k_from else (other, known)
            lo, hi = min(k_from, k_to), max(k_from, k_to)
            f = face(ctx, a, b, angle)
            g = face(ctx, n[lo], n[hi], angle)
            plus = newell(ctx, [x + y for x, y in zip(f, g, strict=True)])
            minus = newell(ctx, [x - y for x, y in zip(f, g, strict=True)])
            return ctx.fdot((plus - minus) / 4, newell(ctx, g))

        mu = ctx.findroot(mixed, (ctx.mpf(-1), ctx.mpf(1)), solver="secant")
        return (known[0] + mu * e[0], known[1] + mu * e[1])

    keys = sorted(s)
    for i in range(0, keys[-1]):
        p[i + 1] = solve(p[i], i, i + 1)
    for i in range(0, keys[0], -1):
        p[i - 1] = solve(p[i], i, i - 1)
    return p, n
