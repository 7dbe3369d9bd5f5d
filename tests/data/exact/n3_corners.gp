\\ Exact certificate (format 1), written by hand for the independent checker's tests (not by tripack).
\\ n = 3: the three corners of the unit triangle; d = 1 (optimal for n = 3).
\\ Derivation: the corners (0,0), (1,0), (1/2, sqrt(3)/2) are pairwise at distance 1, so every pair
\\ is a bond; each corner lies on its two sides. d = 1 is rational: P = x - 1.
\\ K = Q(sqrt 3) = Q[t]/(t^2 - 3), t0 = +sqrt(3) = 1.7320508..., so sqrt3_in_K = t.
\\ given: sqrt(3)/2 = 0.866025403784438646763723170752936183... rounded to 30 decimals
\\ (gp: round(sqrt(3)/2 * 10^30) at \p 100).
\\ Coordinates file (provenance): tests/data/atlas-checker/n3-corners.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n3-corners"; n = 3;
P = x - 1;
d_low = 9/10; d_high = 11/10;
K = t^2 - 3;
t_low = 1732/1000; t_high = 1733/1000;
d_in_K = 1;
sqrt3_in_K = t;
points = [[0, 0], [1, 0], [1/2, t/2]];
rattlers = [];
bonds = [[1, 2], [1, 3], [2, 3], [1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3]];
{given = [
  [0/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30]];}
given_tolerance = 10^-25;
claims = ["existence"];
