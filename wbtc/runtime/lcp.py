"""The LCP of ODE's contact rows and their island's joint rows, solved for wbtc.runtime.ode_solve.

Rows (in this order): n contacts' normal rows, their first friction rows, their second friction rows,
then rows with fixed bounds (friction losses within ±their loss; joint limits, 0 or more; equalities,
unbounded). Row k's force f_k makes its acceleration
a_k = accel_k + (A f)_k reach ref_k − R_k f_k, unless a bound holds it:

- a normal force is 0 or more (0 when the bodies would part faster than asked);
- a friction force lies within ±μ_k × its contact's normal force (ODE's `dContactApprox1`, a box);
- another row's force lies within its own bounds.

ODE's `dWorldStep` solves this exactly (Dantzig's pivoting). Here a projected Gauss-Seidel from
MuJoCo's forces comes first (most substeps are settled in one to three sweeps); when it has not
converged in SWEEPS sweeps (hard rows coupled through light and heavy bodies: a wheel's motor row and
its rims' friction on a robot hundreds of times heavier), pivoting on the rows' states (free, at the
lower bound, at the upper bound) finds the exact solution from where the sweeps left it: one
violated row changes state per pivot, each pivot a dense solve of the free rows.
"""

from __future__ import annotations

import numpy as np

#: Gauss-Seidel sweeps before pivoting (ODE's quickstep default is 20).
SWEEPS = 20
#: Sweeps end once no force changed by more than this share of the largest.
TOLERANCE = 1e-10
#: Most pivots, per row: past them the sweeps' forces are kept.
PIVOTS_PER_ROW = 3

_FREE, _LOWER, _UPPER, _DEAD = 0, -1, 1, 2


def solve(a_mat: np.ndarray, accel: np.ndarray, ref: np.ndarray, reg: np.ndarray, mu: np.ndarray,
          bounds: tuple[np.ndarray, np.ndarray], start: np.ndarray, n: int) -> np.ndarray:
    """The rows' forces (see the module): `mu` of the 2n friction rows, `bounds` (lower, upper) of the rest."""
    total = np.diag(a_mat) + reg
    # A row the bodies' degrees of freedom cannot move (a friction direction along a hinge's axis) has
    # a zero diagonal: it gets no force.
    live = total > 1e-12 * (1.0 + total.max())
    problem = _Problem(mu, bounds[0], bounds[1], n)
    forces, settled = sweeps(a_mat, accel, ref, reg, problem, start * live, live)
    if settled:
        return forces
    exact = pivot(a_mat + np.diag(reg), ref - accel, problem, forces, live)
    return forces if exact is None else exact


class _Problem:
    """The rows' bounds: normals at 0 or more, frictions within ±μ × their normal, the rest within fixed bounds."""

    def __init__(self, mu: np.ndarray, lower: np.ndarray, upper: np.ndarray, n: int) -> None:
        self.mu, self.lower, self.upper, self.n = mu, lower, upper, n

    def bounds(self, forces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each row's (lower, upper) bound at these forces."""
        n = self.n
        normals = np.maximum(forces[:n], 0.0)
        upper = np.concatenate([np.full(n, np.inf), self.mu * np.concatenate([normals, normals]), self.upper])
        lower = np.concatenate([np.zeros(n), -upper[n:3 * n], self.lower])
        return lower, upper


def sweeps(a_mat: np.ndarray, accel: np.ndarray, ref: np.ndarray, reg: np.ndarray, problem: _Problem,
           start: np.ndarray, live: np.ndarray) -> tuple[np.ndarray, bool]:
    """Projected Gauss-Seidel from `start`: the forces, and whether they settled within SWEEPS sweeps."""
    n = problem.n
    acc = accel + a_mat @ start
    inverse = np.where(live, 1.0 / np.where(live, np.diag(a_mat) + reg, 1.0), 0.0)
    # Python floats: scalar arithmetic on NumPy's values costs several times more.
    f, targets, soft, inv = start.tolist(), ref.tolist(), reg.tolist(), inverse.tolist()
    mus, lows, highs = problem.mu.tolist(), problem.lower.tolist(), problem.upper.tolist()
    columns = list(a_mat)  # A is symmetric: row k is column k
    order = [k for i in range(n) for k in (i, i + n, i + 2 * n)] + list(range(3 * n, len(f)))
    for _ in range(SWEEPS):
        largest = 0.0
        for k in order:
            old = f[k]
            value = old - (acc.item(k) + soft[k] * old - targets[k]) * inv[k]
            if k < n:
                value = max(value, 0.0)
            elif k < 3 * n:
                bound = mus[k - n] * f[k % n]
                value = min(max(value, -bound), bound)
            else:
                value = min(max(value, lows[k - 3 * n]), highs[k - 3 * n])
            change = value - old
            if change:
                f[k] = value
                acc += columns[k] * change
                largest = max(largest, abs(change))
        if largest <= TOLERANCE * (1.0 + max(map(abs, f))):
            return np.array(f), True
    return np.array(f), False


def pivot(k_mat: np.ndarray, b: np.ndarray, problem: _Problem, start: np.ndarray,
          live: np.ndarray) -> np.ndarray | None:
    """The exact forces by pivoting from the states `start` implies; None when the pivots run out.

    `k_mat` is A + R and `b` is ref − accel: a free row satisfies (k_mat f)_k = b_k.
    """
    m, n = len(start), problem.n
    lower, upper = problem.bounds(start)
    slack = 1e-9 * (1.0 + np.abs(start))
    state = np.where(start >= upper - slack, _UPPER, np.where(start <= lower + slack, _LOWER, _FREE))
    state[:n] = np.where(start[:n] > 0.0, _FREE, _LOWER)
    state[~live] = _DEAD
    scale = np.where(live, np.diag(k_mat), 1.0)
    tolerance = 1e-9 * (1.0 + float(np.abs(start).max()))
    for _ in range(PIVOTS_PER_ROW * m + 5):
        forces = _forces(k_mat, b, problem, state)
        if forces is None:
            return None
        residual = (k_mat @ forces - b) / scale  # in force units: what the row's own force would change
        violation, row, new_state = _worst(forces, residual, problem, state)
        if violation <= tolerance:
            return forces
        state[row] = new_state
    return None


def _forces(k_mat: np.ndarray, b: np.ndarray, problem: _Problem, state: np.ndarray) -> np.ndarray | None:
    """The forces of the rows in these states: f = P x + q, x solving the free rows' equations."""
    m, n = len(state), problem.n
    free = np.nonzero(state == _FREE)[0]
    column = np.full(m, -1)
    column[free] = np.arange(len(free))
    p_mat = np.zeros((m, len(free)))
    p_mat[free, column[free]] = 1.0
    q = np.zeros(m)
    # A friction row at its bound carries ±μ × its contact's normal force (0 when the contact is open).
    held = np.arange(n, 3 * n)[np.isin(state[n:3 * n], (_LOWER, _UPPER))]
    contact = held % n
    open_normal = column[contact] >= 0
    rows = held[open_normal]
    p_mat[rows, column[contact[open_normal]]] = state[rows] * problem.mu[rows - n]
    # Another row at a bound carries that bound.
    others = np.arange(3 * n, m)
    q[others] = np.where(state[others] == _LOWER, problem.lower, np.where(state[others] == _UPPER, problem.upper, 0.0))
    if not len(free):
        return q
    try:
        x = np.linalg.solve((k_mat @ p_mat)[free], (b - k_mat @ q)[free])
    except np.linalg.LinAlgError:
        return None
    return p_mat @ x + q


def _worst(forces: np.ndarray, residual: np.ndarray, problem: _Problem, state: np.ndarray) -> tuple[float, int, int]:
    """The most violated condition: (its size in force units, its row, the state that row takes)."""
    lower, upper = problem.bounds(forces)
    free = state == _FREE
    candidates = [
        (np.where(free, forces - upper, 0.0), _UPPER),  # a free row past a bound
        (np.where(free, lower - forces, 0.0), _LOWER),
        # a row held at a bound that pulls away from it (a negative residual asks for more force)
        (np.where(state == _LOWER, -residual, 0.0), _FREE),
        (np.where(state == _UPPER, residual, 0.0), _FREE),
    ]
    best = (0.0, -1, _FREE)
    for values, new_state in candidates:
        values = np.nan_to_num(values, nan=0.0, neginf=0.0)
        row = int(np.argmax(values))
        if values[row] > best[0]:
            best = (float(values[row]), row, new_state)
    return best
