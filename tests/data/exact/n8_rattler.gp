\\ Exact certificate (format 1), written by hand for the independent checker's tests (not by tripack).
\\ n = 8 with one rattler; d = 1/3. Start from Delta(4) (the triangular lattice of spacing 1/3, 10
\\ points), drop its two interior bottom points (1/3, 0), (2/3, 0) and its centre (1/2, sqrt(3)/6),
\\ and put a rattler at the rational point (1/2, 1/5) in the hole. A genuine packing with min
\\ distance 1/3, not an optimum for n = 8.
\\ Kept lattice points: corners 1 = (0,0), 2 = (1,0), 3 = (1/2, sqrt(3)/2); on the left side
\\ 4 = (1/6, sqrt(3)/6), 6 = (1/3, sqrt(3)/3); on the right side 5 = (5/6, sqrt(3)/6),
\\ 7 = (2/3, sqrt(3)/3). Bonds (lattice edges, length 1/3): 1-4, 2-5, 4-6, 5-7, 6-7, 3-6, 3-7.
\\ Rattler 8 = (1/2, 1/5): its distances are 0.3447 to 4 and 5, 0.4123 to 6 and 7, 0.5385 to 1 and
\\ 2, 0.6660 to 3, all > 1/3; it is 1/5 from the bottom side and (sqrt(3)/2 - 1/5)/2 = 0.3330 from
\\ the left and right sides, so strictly inside.
\\ K = Q(sqrt 3) = Q[t]/(t^2 - 3), t0 = +sqrt(3). P = 3*x - 1.
\\ given: sqrt(3)/6, sqrt(3)/3, sqrt(3)/2 rounded to 30 decimals (gp: round(v * 10^30) at \p 100);
\\ the rattler's given point is its exact rational point.
\\ A value spanning several lines is wrapped in { } (gp file syntax).
\\ Coordinates file (provenance): tests/data/atlas-checker/n8-rattler.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n8-rattler"; n = 8;
P = 3*x - 1;
d_low = 333/1000; d_high = 334/1000;
K = t^2 - 3;
t_low = 1732/1000; t_high = 1733/1000;
d_in_K = 1/3;
sqrt3_in_K = t;
{points = [[0, 0], [1, 0], [1/2, t/2], [1/6, t/6], [5/6, t/6], [1/3, t/3], [2/3, t/3],
           [1/2, 1/5]];}
rattlers = [8];
{bonds = [[1, 4], [2, 5], [4, 6], [5, 7], [6, 7], [3, 6], [3, 7],
          [1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3], [4, -2], [6, -2], [5, -3], [7, -3]];}
{given = [
  [0/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30],
  [166666666666666666666666666667/10^30, 288675134594812882254574390251/10^30],
  [833333333333333333333333333333/10^30, 288675134594812882254574390251/10^30],
  [333333333333333333333333333333/10^30, 577350269189625764509148780502/10^30],
  [666666666666666666666666666667/10^30, 577350269189625764509148780502/10^30],
  [500000000000000000000000000000/10^30, 200000000000000000000000000000/10^30]];}
given_tolerance = 10^-25;
claims = ["existence"];
