\\ Exact certificate (format 1), written by hand for the independent checker's tests (not by tripack).
\\ n = 6: Delta(3), the hexagonal triangle of 6 points: the corners and the midpoints of the sides;
\\ d = 1/2 (optimal for n = 6, Oler).
\\ Derivation: the 6 points are the triangular lattice of spacing 1/2 inside the triangle; the 9
\\ lattice edges are the disk bonds (distance 1/2), every other pair is at distance sqrt(3)/2 or 1.
\\ Bottom side: points 1, 2, 3; left side: 1, 4, 6; right side: 3, 5, 6. P = 2*x - 1.
\\ This certificate deliberately uses another generator of Q(sqrt 3): K = t^2 - 3/4 (rational
\\ coefficients), t0 = +sqrt(3)/2 = 0.8660254..., so sqrt3_in_K = 2*t and sqrt(3)/4 = t/2.
\\ given: sqrt(3)/4 and sqrt(3)/2 rounded to 30 decimals (gp: round(v * 10^30) at \p 100).
\\ A value spanning several lines is wrapped in { } (gp file syntax: a newline outside braces
\\ ends the statement).
\\ Coordinates file (provenance): tests/data/atlas-checker/n6-delta3.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n6-delta3"; n = 6;
P = 2*x - 1;
d_low = 49/100; d_high = 51/100;
K = t^2 - 3/4;
t_low = 866/1000; t_high = 867/1000;
d_in_K = 1/2;
sqrt3_in_K = 2*t;
points = [[0, 0], [1/2, 0], [1, 0], [1/4, t/2], [3/4, t/2], [1/2, t]];
rattlers = [];
{bonds = [[1, 2], [2, 3], [1, 4], [2, 4], [2, 5], [3, 5], [4, 5], [4, 6], [5, 6],
          [1, -1], [2, -1], [3, -1], [1, -2], [4, -2], [6, -2], [3, -3], [5, -3], [6, -3]];}
{given = [
  [0/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [250000000000000000000000000000/10^30, 433012701892219323381861585376/10^30],
  [750000000000000000000000000000/10^30, 433012701892219323381861585376/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30]];}
given_tolerance = 10^-25;
claims = ["existence"];
