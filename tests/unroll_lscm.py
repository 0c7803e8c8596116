#!/usr/bin/python3
# unroll_lscm.py: an independent least-squares conformal map (Levy et
# al. 2002) of a bezier-surface record on the N x N grid mesh unroll -n N
# makes, for tests/unroll.sh: prints its largest and mean edge strain,
# at the uniform scale that makes the largest least (the map leaves the
# scale free).  Usage: unroll_lscm.py FILE N
import sys
import numpy as np
from math import comb
import scipy.sparse as sp
import scipy.sparse.linalg as sla

def read(path):
    rows = []; m = n = None
    for line in open(path):
        w = line.split()
        if not w: continue
        if w[0] == 'bezier-surface':
            for kv in w[1:]:
                k, v = kv.split('=')
                if k == 'm': m = int(v)
                if k == 'n': n = int(v)
            continue
        rows.append([float(x) for x in w])
    return np.array(rows).reshape(m + 1, n + 1, 3), m, n

def bern(d, t):
    return np.array([comb(d, i) * t**i * (1 - t)**(d - i) for i in range(d + 1)])

P, m, n = read(sys.argv[1]); N = int(sys.argv[2])
t = np.arange(N + 1) / N
Bu = np.array([bern(m, x) for x in t]); Bv = np.array([bern(n, x) for x in t])
X = np.einsum('ai,bj,ijc->abc', Bu, Bv, P).reshape(-1, 3)
tris = []
for i in range(N):
    for j in range(N):
        a = i * (N + 1) + j; b = a + N + 1
        tris += [(a, b, b + 1), (a, b + 1, a + 1)]
tris = np.array(tris); nv = len(X)
# LSCM: for each triangle, local orthonormal coords, complex gradient rows
rows, cols, vals = [], [], []
for r, (i, j, k) in enumerate(tris):
    p0, p1, p2 = X[i], X[j], X[k]
    e1 = p1 - p0; l = np.linalg.norm(e1); ex = e1 / l
    nrm = np.cross(e1, p2 - p0); A2 = np.linalg.norm(nrm); ey = np.cross(nrm / A2, ex)
    q = [np.zeros(2), np.array([l, 0.0]), np.array([(p2 - p0) @ ex, (p2 - p0) @ ey])]
    # W_j = (x_k - x_i) + i (y_k - y_i) cyclic, divided by sqrt(area)
    s = 1 / np.sqrt(A2)
    for a, vidx in enumerate((i, j, k)):
        b, c = q[(a + 1) % 3], q[(a + 2) % 3]
        W = complex(c[0] - b[0], c[1] - b[1]) * s
        # residual rows: real and imaginary parts of sum W_j (u_j + i v_j)
        rows += [2 * r, 2 * r, 2 * r + 1, 2 * r + 1]
        cols += [vidx, nv + vidx, vidx, nv + vidx]
        vals += [W.real, -W.imag, W.imag, W.real]
M = sp.csr_matrix((vals, (rows, cols)), shape=(2 * len(tris), 2 * nv))
# pin two far vertices at their 3-D distance apart
pa, pb = 0, nv - 1
d = np.linalg.norm(X[pb] - X[pa])
fixed = {pa: 0.0, nv + pa: 0.0, pb: d, nv + pb: 0.0}
free = [c for c in range(2 * nv) if c not in fixed]
fv = np.zeros(2 * nv)
for c, v in fixed.items(): fv[c] = v
rhs = -M @ fv
sol = sla.lsqr(M[:, free], rhs, atol=1e-14, btol=1e-14, iter_lim=100000)[0]
fv[free] = sol
U = np.stack([fv[:nv], fv[nv:]], 1)
E = set()
for (i, j, k) in tris:
    for a, b in ((i, j), (j, k), (k, i)):
        E.add((min(a, b), max(a, b)))
E = np.array(sorted(E))
l3 = np.linalg.norm(X[E[:, 0]] - X[E[:, 1]], axis=1)
l2 = np.linalg.norm(U[E[:, 0]] - U[E[:, 1]], axis=1)
ok = l3 > 0
l3, l2 = l3[ok], l2[ok]
# the best scale for the largest strain: golden search on the max
def worst(s): return np.max(np.abs(s * l2 / l3 - 1))
lo, hi = 0.5 * l3.sum() / l2.sum(), 2 * l3.sum() / l2.sum()
for _ in range(200):
    a = lo + (hi - lo) * 0.382; b = lo + (hi - lo) * 0.618
    if worst(a) < worst(b): hi = b
    else: lo = a
s = (lo + hi) / 2
print("%.6g %.6g" % (worst(s), np.mean(np.abs(s * l2 / l3 - 1))))
