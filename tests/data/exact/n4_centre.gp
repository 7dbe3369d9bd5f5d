\\ Exact certificate (format 1), written by hand for the independent checker's tests (not by tripack).
\\ n = 4: the three corners and the centroid; d = 1/sqrt(3) = sqrt(3)/3 (optimal for n = 4).
\\ Derivation: the centroid (1/2, sqrt(3)/6) is at distance sqrt(1/4 + 1/12) = sqrt(1/3) from each
\\ corner; the corners are 1 apart (> d). The centroid is at distance sqrt(3)/6 = 0.2887 from each
\\ side, so it has no wall bond. d^2 = 1/3: P = 3*x^2 - 1 (roots +-0.57735). In K = Q[t]/(t^2 - 3)
\\ with t0 = +sqrt(3): d = t/3.
\\ given: sqrt(3)/2 and sqrt(3)/6 rounded to 30 decimals (gp: round(v * 10^30) at \p 100).
\\ A value spanning several lines is wrapped in { } (gp file syntax: a newline outside braces
\\ ends the statement).
\\ Coordinates file (provenance): tests/data/atlas-checker/n4-centre.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n4-centre"; n = 4;
P = 3*x^2 - 1;
d_low = 577/1000; d_high = 578/1000;
K = t^2 - 3;
t_low = 1732/1000; t_high = 1733/1000;
d_in_K = t/3;
sqrt3_in_K = t;
points = [[0, 0], [1, 0], [1/2, t/2], [1/2, t/6]];
rattlers = [];
bonds = [[1, 4], [2, 4], [3, 4], [1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3]];
{given = [
  [0/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30],
  [500000000000000000000000000000/10^30, 288675134594812882254574390251/10^30]];}
given_tolerance = 10^-25;
claims = ["existence"];
