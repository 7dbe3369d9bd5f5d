\\ Exact certificate (format 1) claiming "strict-local-optimum", written by hand for the independent
\\ checker's tests (not by tripack). The claim is FALSE and the checker must REJECT it with
\\ "FAIL rigidity" while stress-balance and stress-positive pass: a strictly positive stress
\\ alone does not make a strict local optimum.
\\ n = 3 on the vertical line x = 1/2: 1 = the apex (1/2, sqrt(3)/2) (on the left and right sides),
\\ 2 = the bottom midpoint (1/2, 0) (on the bottom side), 3 = (1/2, sqrt(3)/4) halfway between them.
\\ d = sqrt(3)/4 = 0.4330 (pairs 1-3 and 2-3; 1-2 is sqrt(3)/2 apart); P = 16*x^2 - 3. Point 3 is
\\ sqrt(3)/8 = 0.2165 from the left and right sides, point 2 sqrt(3)/4 from them: strictly inside.
\\ A genuine configuration (existence holds), far from optimal (d = 1 for n = 3).
\\ K = t^2 - 3, t0 = sqrt(3), d = t/4.
\\ Stress: with gp from G over K (checker/README.md): rank G = 4 < 6 (5 bonds; nothing holds x2 or
\\ x3: every row is vertical in those columns), matker(G~) has dimension 1, scaled to pair entries 1:
\\ [1, 1, t/8, t/8, t/4]. By hand: at 3 the pair rows (0, -s/4) and (0, s/4) cancel (s = sqrt 3); at
\\ 2 the pair row x2 - x3 = (0, -s/4) is balanced by the bottom wall (0, 1)*s/4; at the apex the pair
\\ row (0, s/4) by (s, -1)*s/8 + (-s, -1)*s/8 = (0, -s/4). All positive, yet disks 2 and 3 can
\\ slide sideways at first order (G y = 0 for y = moving x2 and x3).
\\ given: sqrt(3)/2 and sqrt(3)/4 rounded to 30 decimals (gp: round(v * 10^30) at \p 100).
\\ Coordinates file (provenance): tests/data/atlas-checker/n3-collinear.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n3-collinear"; n = 3;
P = 16*x^2 - 3;
d_low = 433/1000; d_high = 434/1000;
K = t^2 - 3;
t_low = 1732/1000; t_high = 1733/1000;
d_in_K = t/4;
sqrt3_in_K = t;
points = [[1/2, t/2], [1/2, 0], [1/2, t/4]];
rattlers = [];
bonds = [[1, 3], [2, 3], [1, -2], [1, -3], [2, -1]];
stress = [1, 1, t/8, t/8, t/4];
{given = [
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30],
  [500000000000000000000000000000/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 433012701892219323381861585376/10^30]];}
given_tolerance = 10^-25;
claims = ["existence", "strict-local-optimum"];
