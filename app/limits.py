"""The work budget of a request, checked before any computation (settings in app/settings.py)."""

from __future__ import annotations

from app import admission
from app.geometry.precision import GUARD_DIGITS, Arithmetic, arithmetic
from app.settings import Settings

#: The cost of an mp step grows like (digits + this): below ~200 digits the Python overhead of
#: each mpmath operation dominates. Measured when this was set: 1000 D4b vertices took 0.5 s at
#: 50 digits and 1.4 s at 1000 digits (gmpy2 backend); since the checks of Section 5 joined
#: D4b they take about 1.7–2.1 s at 50 digits, 2.8 s at 500 and 5.7 s at 1000
#: (bench/mp.py, docs/performance.md), so the fixed part now weighs like ~800 digits.
MP_OVERHEAD_DIGITS = 200


# --- estimated cost -------------------------------------------------------------------------
# Seconds are CPU seconds on one free core of the 2-core development machine, bytes the peak
# working memory of one request (arrays, companions, checks and the encoded answer), both
# measured with bench/costs.py and rounded up (docs/reliability.md). Time is linear in the
# vertices and steps in float64; in mp every step costs a few mpmath calls whose price grows
# with the digits.

#: float64: seconds and bytes per vertex of a polygon (computed, checked and encoded as JSON).
#: From 10^5 vertices (D4b) runs its fits and one of its rings on second threads of the request
#: (``d4b.checks.FITS_THREADED_FROM``, ``d4b.curvature.RINGS_THREADED_FROM``): the same CPU
#: seconds (≈ 0.04 and 0.045 s at 10^6, far inside the 4 s charged), two threads at a time (the
#: fits are joined before the rings start).
F64_VERTEX_SECONDS = 4e-6
F64_VERTEX_BYTES = 800
#: float64: seconds per sequential construction step (from index 0 to i_min and i_max): the
#: compiled recursions take 20–110 ns a step (bench/compiled.py), twice that is allowed.
F64_STEP_SECONDS = 2e-7
#: float64 surfaces: seconds and bytes per mesh vertex (GLB or JSON with per-face K and H).
F64_MESH_VERTEX_SECONDS = 4e-6
F64_MESH_VERTEX_BYTES = 2000
#: mp: seconds and bytes per step at few digits; both grow like (1 + digits / MP_DIGITS_SCALE).
#: (D2b) and (D4b) with every check, the dearest, take about 3.3 ms a step at 50 digits
#: (answer encoded); the others a fraction of that (MP_STEP_SHARE).
MP_STEP_SECONDS = 3.5e-3
MP_STEP_BYTES = 24_000
MP_DIGITS_SCALE = 400
MP_STEP_SHARE = {"d1": 0.25, "d2a-quad": 0.45, "d2a-hex": 0.45, "d3": 0.35, "smooth": 0.15}
#: mp curves of /discretizations and /relations, computed on rigorous balls (python-flint arb,
#: app/geometry/balls.py): seconds per step grow like (1 + w / BALL_DIGITS_SCALE_SECONDS[kind])
#: and bytes like (1 + w / BALL_DIGITS_SCALE) in the *working* digits w = digits + guard digits
#: + the digits a construction's radii grow by (``balls.extra_digits``: for (D4b) about
#: 2|i|·ln((h+d)/(h−d))/ln 10, so they count here). Seconds measured with bench/ball_costs.py
#: (every discretization at 50, 500 and 1000 digits, 201 and 801 vertices, every check, JSON,
#: CPU time, load 9–10 on the 2-core machine; docs/performance.md): (D4b) 0.39 ms a step at 50
#: digits, 0.89 ms at 500, 1.6 ms at 1000 (801 vertices), its time growing with the digits as
#: w/150 (Section 5's transcendental functions); the others are dominated by the Python cost of
#: each operation and grow as w/300. The shares are set so that a measured request used at most
#: about 0.75–0.85 of its estimate under that load (run to run ±25 %; a quiet host is faster):
#: refusals still come early, never late. The coefficients before overestimated the others 2–5×
#: at 500–1000 digits (measured/estimated 0.21–0.37 there) and D4b 1.6–4.2×. Peak memory 13 KB
#: a step at 50 digits, 50 KB at 1000 (D4b).
BALL_STEP_SECONDS = 4e-4
BALL_STEP_BYTES = 8_000
BALL_DIGITS_SCALE = 150
BALL_DIGITS_SCALE_SECONDS = {"d4b": 150}
#: (D4b) carries its extra digits in the construction only (``Ball.recursions_only``): its time
#: grows with a quarter of them (measured: 3991 vertices at 50 digits, extra digits ≈ 350,
#: 0.34 ms a step against 0.39 ms at 801 vertices, extra ≈ 70; the full weight overestimated
#: that request 4.2×).
BALL_EXTRA_DIGITS_WEIGHT = {"d4b": 0.25}
BALL_DIGITS_SCALE_SECONDS_OTHERS = 300
BALL_STEP_SHARE = {
    "d4b": 0.85,
    "d1": 0.35,
    "d3": 0.3,
    "d4a": 0.7,
    "d2a-quad": 0.5,
    "d2a-hex": 0.5,
    "d2b": 1.0,
}
#: Bytes per step: the shares of time measured before (memory was not re-measured).
BALL_BYTES_SHARE = {
    "d1": 0.3,
    "d3": 0.35,
    "d4a": 0.8,
    "d2a-quad": 0.55,
    "d2a-hex": 0.65,
    "d2b": 0.7,
}
#: mp surfaces: per mesh vertex (the mesh, its normals and per-face curvatures in mpmath).
MP_MESH_VERTEX_SECONDS = 2.2e-3
MP_MESH_VERTEX_BYTES = 12_000
#: refinement studies, per construction step of their work: float64 and mp.
F64_STUDY_STEP_SECONDS = 2e-6
F64_STUDY_STEP_BYTES = 400
MP_STUDY_STEP_SECONDS = 1e-4
MP_STUDY_STEP_BYTES = 4_000
#: Every request: parsing, encoding, the interpreter's bookkeeping.
BASE_SECONDS = 3e-3
BASE_BYTES = 256 * 1024


def mp_factor(digits: int) -> float:
    """How much dearer an mp step is at ``digits`` than at a few digits."""
    return 1 + digits / MP_DIGITS_SCALE


def admit(settings: Settings, seconds: float, nbytes: float, parameter: str, value: object) -> None:
    """Refuse work that could never be admitted (422 naming ``parameter``), else charge the
    request's admission ticket (a 503 when the worker's budget is taken, app/admission.py)."""
    seconds += BASE_SECONDS
    nbytes = int(nbytes + BASE_BYTES)
    # alone on a free core it must fit both the worker's budget and the time limit; past either
    # waiting cannot help (a 422, not a 503 asking to retry)
    ceiling, setting = min(
        (settings.admission_seconds, "DCOSH_ADMISSION_SECONDS"),
        (settings.time_limit, "DCOSH_TIME_LIMIT"),
    )
    if seconds > ceiling:
        raise LimitExceededError(
            parameter,
            f"estimated time <= {ceiling:g} s ({setting}; this request needs about "
            f"{seconds:.3g} s)",
            value,
        )
    if nbytes > settings.admission_bytes:
        raise LimitExceededError(
            parameter,
            f"estimated memory <= {settings.admission_bytes // 2**20} MiB "
            f"(DCOSH_ADMISSION_BYTES; this request needs about {nbytes / 2**20:.0f} MiB)",
            value,
        )
    admission.charge(seconds, nbytes, parameter)


def curve_cost(
    vertices: int,
    steps: int,
    precision: str,
    digits: int,
    kind: str | None = None,
    extra_digits: int | None = None,
) -> tuple[float, float]:
    """(seconds, bytes) of one polygon: ``vertices`` answered, ``steps`` computed; ``kind`` is
    the discretization's id (None: priced as the dearest). ``extra_digits`` (not None: the
    curve is computed on balls) are the digits its radii grow by (``balls.extra_digits``)."""
    if precision == "mp" and extra_digits is not None:
        working = digits + GUARD_DIGITS + extra_digits
        # unknown kind (None): priced above the dearest, D4b, with every extra digit
        scale = BALL_DIGITS_SCALE_SECONDS.get(kind or "d4b", BALL_DIGITS_SCALE_SECONDS_OTHERS)
        weight = BALL_EXTRA_DIGITS_WEIGHT.get(kind or "", 1.0)
        weighted = digits + GUARD_DIGITS + extra_digits * weight
        seconds = (1 + weighted / scale) * BALL_STEP_SHARE.get(kind or "", 1.0)
        nbytes = (1 + working / BALL_DIGITS_SCALE) * BALL_BYTES_SHARE.get(kind or "", 1.0)
        work = max(vertices, steps)
        return BALL_STEP_SECONDS * seconds * work, BALL_STEP_BYTES * nbytes * work
    if precision == "mp":
        factor = mp_factor(digits) * MP_STEP_SHARE.get(kind or "", 1.0)
        work = max(vertices, steps)
        return MP_STEP_SECONDS * factor * work, MP_STEP_BYTES * factor * work
    constructed = steps if steps > vertices else 0
    return (
        F64_VERTEX_SECONDS * vertices + F64_STEP_SECONDS * constructed,
        F64_VERTEX_BYTES * max(vertices, constructed),
    )


def mesh_cost(vertices: int, precision: str, digits: int) -> tuple[float, float]:
    """(seconds, bytes) of a surface mesh of ``vertices`` vertices (its meridian apart)."""
    if precision == "mp":
        factor = mp_factor(digits)
        return (
            MP_MESH_VERTEX_SECONDS * factor * vertices,
            MP_MESH_VERTEX_BYTES * factor * vertices,
        )
    return F64_MESH_VERTEX_SECONDS * vertices, F64_MESH_VERTEX_BYTES * vertices


def study_cost(work: int, precision: str, digits: int) -> tuple[float, float]:
    """(seconds, bytes) of a refinement study of ``work`` construction steps."""
    if precision == "mp":
        factor = mp_factor(digits)
        return MP_STUDY_STEP_SECONDS * factor * work, MP_STUDY_STEP_BYTES * factor * work
    return F64_STUDY_STEP_SECONDS * work, F64_STUDY_STEP_BYTES * work


class LimitExceededError(ValueError):
    """A request asks for more work than the configured limits allow (a 422, not a 500)."""

    def __init__(self, parameter: str, constraint: str, value: object) -> None:
        self.parameter = parameter
        self.constraint = constraint
        self.value = value
        super().__init__(f"{parameter} must satisfy {constraint}, got {value!r}")


def enforce_range(
    settings: Settings,
    i_min: int,
    i_max: int,
    method: str,
    precision: str,
    digits: int,
    kind: str | None = None,
    extra_digits: int | None = None,
) -> None:
    """Refuse oversize index ranges, long constructions and expensive mp requests, then charge
    the request's estimated cost (``kind``: the discretization's id, for its mp price;
    ``extra_digits``: set when mp is computed on balls, see ``curve_cost``).

    The order i_min <= i_max is the core's to check (a domain error); here an empty range
    simply costs nothing.
    """
    vertices = max(0, i_max - i_min + 1)
    if vertices > settings.max_vertices:
        raise LimitExceededError(
            "i_max", f"i_max − i_min + 1 <= {settings.max_vertices} (vertices)", i_max
        )
    steps = vertices
    if method == "construction":
        steps = max(abs(i_min), abs(i_max), vertices) + 1
        if steps > settings.max_construction_steps:
            name, value = ("i_max", i_max) if abs(i_max) >= abs(i_min) else ("i_min", i_min)
            raise LimitExceededError(
                name,
                f"max(|i_min|, |i_max|) < {settings.max_construction_steps} with "
                "method=construction (use method=closed-form for longer ranges)",
                value,
            )
    if precision == "mp":
        enforce_digits(settings, digits)
        if (digits + MP_OVERHEAD_DIGITS) * steps > settings.max_mp_work:
            raise LimitExceededError(
                "digits",
                f"(digits + {MP_OVERHEAD_DIGITS}) × steps <= {settings.max_mp_work} in "
                f"precision=mp (this range needs {steps} steps)",
                digits,
            )
    seconds, nbytes = curve_cost(vertices, steps, precision, digits, kind, extra_digits)
    driver = ("digits", digits) if precision == "mp" else ("i_max", i_max)
    admit(settings, seconds, nbytes, *driver)


def enforce_digits(settings: Settings, digits: int) -> None:
    """Refuse more digits than configured."""
    if digits > settings.max_digits:
        raise LimitExceededError("digits", f"1 <= digits <= {settings.max_digits}", digits)


def enforce_mesh(settings: Settings, rows: int, columns: int, precision: str, digits: int) -> None:
    """Refuse surface meshes over the vertex budget (and mp meshes over the mp budget)."""
    vertices = rows * columns
    if vertices > settings.max_mesh_vertices:
        raise LimitExceededError(
            "m",
            f"meridian vertices × vertices around <= {settings.max_mesh_vertices} "
            f"(here {rows} × {columns})",
            vertices,
        )
    if precision == "mp" and digits * vertices > settings.max_mp_work:
        raise LimitExceededError(
            "digits",
            f"digits × mesh vertices <= {settings.max_mp_work} in precision=mp "
            f"(this mesh has {vertices} vertices)",
            digits,
        )
    seconds, nbytes = mesh_cost(vertices, precision, digits)
    admit(settings, seconds, nbytes, "m", vertices)


#: A figure (GET /figures/{id}.svg): CPU seconds on a free core and bytes, a fixed part and a
#: part per vertex of its index range. Measured (CPU time, in float64) on the dearest figure per
#: vertex, figure-3 (D4a, its Darboux transform and p): 118 ms for 1,921 vertices, 61 µs a
#: vertex; figure-2's tractrix at its 20,001 samples 6 µs, figure-8 at j = 1000 15 µs.
FIGURE_SECONDS = 0.005
FIGURE_VERTEX_SECONDS = 70e-6
FIGURE_BYTES = 2**20
FIGURE_VERTEX_BYTES = 4096


def figure_cost(vertices: int) -> tuple[float, float]:
    """(seconds, bytes) of a figure drawing ``vertices`` vertices per polygon."""
    vertices = max(0, vertices)
    return (
        FIGURE_SECONDS + FIGURE_VERTEX_SECONDS * vertices,
        FIGURE_BYTES + FIGURE_VERTEX_BYTES * vertices,
    )


def charge_figure(settings: Settings, i_min: int, i_max: int) -> None:
    """Charge a figure's estimated cost (its size is refused by ``enforce_drawing`` first)."""
    seconds, nbytes = figure_cost(i_max - i_min + 1)
    admit(settings, seconds, nbytes, "i_max", i_max)


def enforce_drawing(settings: Settings, i_min: int, i_max: int) -> None:
    """Refuse pictures of polygons with more vertices than ``max_svg_vertices``."""
    vertices = max(0, i_max - i_min + 1)
    if vertices > settings.max_svg_vertices:
        raise LimitExceededError(
            "i_max",
            f"i_max − i_min + 1 <= {settings.max_svg_vertices} (vertices) for a picture "
            "(format=svg or /figures); use format=json or csv for longer ranges",
            i_max,
        )


def enforce_study(
    settings: Settings,
    arguments: dict[str, object],
    size: tuple[int, int],
    mp_work: int,
    precision: str,
    digits: int,
) -> None:
    """Refuse refinement studies over the limits: levels, samples, construction steps, mp work.

    ``size`` is (construction steps, sample points) summed over the levels, ``mp_work`` the
    study's cost in construction steps; both computed from the parameters before any work.
    """
    levels = arguments.get("levels")
    if isinstance(levels, int) and levels > settings.max_convergence_levels:
        raise LimitExceededError("levels", f"levels <= {settings.max_convergence_levels}", levels)
    samples = arguments.get("samples")
    if isinstance(samples, int) and samples > settings.max_convergence_samples:
        raise LimitExceededError(
            "samples", f"samples <= {settings.max_convergence_samples}", samples
        )
    built, _ = size
    if built > settings.max_convergence_steps:
        raise LimitExceededError(
            "levels",
            f"construction steps over all levels <= {settings.max_convergence_steps} (this "
            f"study needs {built}: fewer levels, a larger d0 or a smaller x_max)",
            levels,
        )
    if precision == "mp":
        enforce_digits(settings, digits)
        if (digits + MP_OVERHEAD_DIGITS) * mp_work > settings.max_mp_work:
            raise LimitExceededError(
                "digits",
                f"(digits + {MP_OVERHEAD_DIGITS}) × work <= {settings.max_mp_work} in "
                f"precision=mp (this study's work is {mp_work} construction steps; use fewer "
                "levels or samples)",
                digits,
            )
    seconds, nbytes = study_cost(max(mp_work, built), precision, digits)
    admit(settings, seconds, nbytes, "levels", levels)


def enforce_relation_row(settings: Settings, parameter: str, i_min: int, i_max: int) -> None:
    """Refuse a row of GET /relations with more vertices than ``max_relation_vertices``."""
    vertices = max(0, i_max - i_min + 1)
    if vertices > settings.max_relation_vertices:
        raise LimitExceededError(
            parameter,
            f"i_max − i_min + 1 <= {settings.max_relation_vertices} (vertices of one row)",
            i_max,
        )


def timed_arithmetic(settings: Settings, precision: str, digits: int) -> Arithmetic:
    """The request's arithmetic with its clock started (DCOSH_TIME_LIMIT): a computation past
    the limit stops with a 422 naming what drives its cost (digits in mp, else the range)."""
    ar = arithmetic(precision, digits)  # type: ignore[arg-type]
    ar.start_clock(settings.time_limit, "digits" if precision == "mp" else "i_max")
    deadline = admission.deadline()
    if deadline is not None:  # the clock runs from the request's arrival: waiting counts
        ar.deadline = deadline
    return ar
