\\ Exact certificate (format 1) claiming "strict-local-optimum", written by hand for the independent
\\ checker's tests (not by tripack).
\\ n = 4: the three corners and the centroid, d = 1/sqrt(3); the configuration of ../n4_centre.gp
\\ (derivation there), written this time in the degree-4 field K = Q(sqrt 2, sqrt 3) =
\\ Q[t]/(t^4 - 10*t^2 + 1), t0 = sqrt(2) + sqrt(3) = 3.14626..., where sqrt(3) = (11*t - t^3)/2 (as
\\ in ../n4_diamond_sqrt2.gp; gp: Mod((11*t - t^3)/2, K)^2 == 3), so d = sqrt(3)/3 = (11*t - t^3)/6,
\\ sqrt(3)/2 = (11*t - t^3)/4, sqrt(3)/6 = (11*t - t^3)/12. K is larger than needed (everything is in
\\ Q(sqrt 3)); format 1 allows that, and it exercises the rank and the balance over a degree-4 field.
\\ Rigidity: 4 held disks, 8 coordinates, 9 bonds; the corners are pinned by their wall rows, the
\\ centroid by its three pair rows (directions 120 degrees apart): rank 8 (gp matrank over K).
\\ Stress: with gp from G over K (checker/README.md): matker(G~) has dimension 1 (9 - 8); scaled so
\\ that the pair entries are 1 it is [1, 1, 1, s/3, s/6, s/3, s/6, s/6, s/6], s = sqrt(3).
\\ By hand: at the centroid c the pair rows sum to 3c - (corners) = 0; at corner 1 the pair row
\\ x1 - c = (-1/2, -s/6) is balanced by the bottom wall (0, 1) * s/3 and the left wall (s, -1) * s/6:
\\ (1/2, s/3 - s/6) = (1/2, s/6). Positive at t0: 1, 0.577, 0.289.
\\ given: as in ../n4_centre.gp.
\\ A value spanning several lines is wrapped in { } (gp file syntax).
\\ Coordinates file (provenance): tests/data/atlas-checker/n4-centre-slo.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n4-centre-slo"; n = 4;
P = 3*x^2 - 1;
d_low = 577/1000; d_high = 578/1000;
K = t^4 - 10*t^2 + 1;
t_low = 3146/1000; t_high = 3147/1000;
d_in_K = (11*t - t^3)/6;
sqrt3_in_K = (11*t - t^3)/2;
points = [[0, 0], [1, 0], [1/2, (11*t - t^3)/4], [1/2, (11*t - t^3)/12]];
rattlers = [];
bonds = [[1, 4], [2, 4], [3, 4], [1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3]];
{stress = [1, 1, 1, (11*t - t^3)/6, (11*t - t^3)/12, (11*t - t^3)/6, (11*t - t^3)/12,
           (11*t - t^3)/12, (11*t - t^3)/12];}
{given = [
  [0/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30],
  [500000000000000000000000000000/10^30, 288675134594812882254574390251/10^30]];}
given_tolerance = 10^-25;
claims = ["existence", "strict-local-optimum"];
