\\ Exact certificate (format 1), written by hand for the independent checker's tests (not by tripack).
\\ n = 5: a square of side s standing on the bottom side, its top corners on the left and right
\\ sides, plus the apex; d = s = 2*sqrt(3) - 3 = 0.4641... A genuine packing with a bond graph that
\\ pins d (6 disk bonds for 5 unknowns), though not the optimum for n = 5 (that is d = 1/2).
\\ Derivation: square corners BL = (a, 0), BR = (a + s, 0), TL = (a, s), TR = (a + s, s), symmetric
\\ about x = 1/2, so a = (1 - s)/2. TL on the left side: sqrt(3)*a = s, so s*(2 + sqrt(3)) = sqrt(3),
\\ s = sqrt(3)*(2 - sqrt(3)) = 2*sqrt(3) - 3 and a = 2 - sqrt(3). TR is then on the right side by
\\ symmetry. The apex T = (1/2, sqrt(3)/2) is 1 - 2a = 2*sqrt(3) - 3 = s from TL along the left
\\ side (TL is 2a from the origin), and likewise from TR. Other distances: the square's diagonals
\\ s*sqrt(2) = 0.656, BL-T and BR-T = 0.896. d = -3 + 2*sqrt(3) is a root of x^2 + 6*x - 3.
\\ This certificate uses d itself as the generator: K = t^2 + 6*t - 3, t0 = 2*sqrt(3) - 3 = d (the
\\ other root is -3 - 2*sqrt(3)), so d_in_K = t, sqrt(3) = (t + 3)/2, a = 2 - sqrt(3) = (1 - t)/2,
\\ a + s = (1 + t)/2, sqrt(3)/2 = (t + 3)/4.
\\ Points: 1 = BL, 2 = BR, 3 = TL, 4 = TR, 5 = T.
\\ given: 2 - sqrt(3), sqrt(3) - 1, 2*sqrt(3) - 3 and sqrt(3)/2 rounded to 30 decimals
\\ (gp: round(v * 10^30) at \p 100).
\\ A value spanning several lines is wrapped in { } (gp file syntax).
\\ Coordinates file (provenance): tests/data/atlas-checker/n5-square.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n5-square"; n = 5;
P = x^2 + 6*x - 3;
d_low = 464/1000; d_high = 465/1000;
K = t^2 + 6*t - 3;
t_low = 464/1000; t_high = 465/1000;
d_in_K = t;
sqrt3_in_K = (t + 3)/2;
points = [[(1 - t)/2, 0], [(1 + t)/2, 0], [(1 - t)/2, t], [(1 + t)/2, t], [1/2, (t + 3)/4]];
rattlers = [];
{bonds = [[1, 2], [1, 3], [2, 4], [3, 4], [3, 5], [4, 5],
          [1, -1], [2, -1], [3, -2], [4, -3], [5, -2], [5, -3]];}
{given = [
  [267949192431122706472553658494/10^30, 0/10^30],
  [732050807568877293527446341506/10^30, 0/10^30],
  [267949192431122706472553658494/10^30, 464101615137754587054892683012/10^30],
  [732050807568877293527446341506/10^30, 464101615137754587054892683012/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30]];}
given_tolerance = 10^-25;
claims = ["existence"];
