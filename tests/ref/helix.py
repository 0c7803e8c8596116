#!/usr/bin/env python3
# tests/ref/helix.py: the reference values of tests/bezier.c for the
# paper's Example 3.3, computed independently of loft (optional; needs
# mpmath; not run by make check).
# Independent check of Carriazo et al. Example 3.3 with mpmath at 30 digits:
# numerical integration by mpmath.quad (tanh-sinh), normals from
# hand-derived formulas: helix (cos 2pi t, sin 2pi t, t) has principal
# normal (-cos 2pi t, -sin 2pi t, 0).
from mpmath import mp, mpf, cos, sin, pi, quad, binomial, matrix, lu_solve
mp.dps = 30
def alpha(t): return [cos(2*pi*t), sin(2*pi*t), t]
def nrm(t): return [-cos(2*pi*t), -sin(2*pi*t), mpf(0)]
def B(n,i,t): return binomial(n,i)*t**i*(1-t)**(n-i)
for n in (2,3,4,5):
    ts=[mpf(i)/n for i in range(n+1)]
    Q=[alpha(t) for t in ts]
    N=[nrm(t) for t in ts]
    idx=list(range(1,n))
    A=matrix(len(idx),len(idx)); b=matrix(len(idx),1)
    for a,j in enumerate(idx):
        for c,i in enumerate(idx):
            A[a,c]=sum(N[i][k]*N[j][k] for k in range(3))*quad(lambda t:B(n,i,t)*B(n,j,t),[0,1])
        b[a]=quad(lambda t: sum(N[j][k]*(alpha(t)[k]-sum(Q[i][k]*B(n,i,t) for i in range(n+1))) for k in range(3))*B(n,j,t),[0,1])
    lam=lu_solve(A,b)
    P=[list(q) for q in Q]
    for a,j in enumerate(idx):
        for k in range(3): P[j][k]+=lam[a]*N[j][k]
    F=quad(lambda t: sum((alpha(t)[k]-sum(P[i][k]*B(n,i,t) for i in range(n+1)))**2 for k in range(3)),[0,1])
    print(n, mp.nstr(F,20))
