\\ Exact certificate (format 1), written by hand for the independent checker's tests (not by tripack).
\\ n = 4: a square of side d turned by 45 degrees (a "diamond"), bottom vertex B = (1/2, 0) on the
\\ bottom side, left vertex L on the left side, right vertex R on the right side, top vertex U
\\ inside. d = (3*sqrt(2) - sqrt(6))/4 = 0.44828..., which is NOT in Q(sqrt 3), so K is the
\\ degree-4 field Q(sqrt 2, sqrt 3). A genuine configuration (min distance d, attained by the 4
\\ sides of the square), but not rigid (the rhombus can flex) and not an optimum.
\\ Derivation: L = (1/2 - h, h) with h = d/sqrt(2); L on the left side: sqrt(3)*(1/2 - h) = h, so
\\ h = sqrt(3)/(2*(1 + sqrt(3))) = (3 - sqrt(3))/4 and d = sqrt(2)*h = (3*sqrt(2) - sqrt(6))/4.
\\ L = ((sqrt(3) - 1)/4, (3 - sqrt(3))/4), R = ((5 - sqrt(3))/4, (3 - sqrt(3))/4) (mirror image, on
\\ the right side), U = (1/2, 2*h) = (1/2, (3 - sqrt(3))/2). The diagonals are d*sqrt(2) = 0.634 > d.
\\ All coordinates lie in Q(sqrt 3); only d needs sqrt(2).
\\ d^2 = (6 - 3*sqrt(3))/4, so (4*d^2 - 6)^2 = 27: P = 16*x^4 - 48*x^2 + 9, irreducible (gp
\\ polisirreducible), real roots +-0.44829, +-1.67303.
\\ K = t^4 - 10*t^2 + 1, the minimal polynomial of t0 = sqrt(2) + sqrt(3) = 3.14626...; in K
\\ (checked with gp, Mod arithmetic): sqrt(2) = (t^3 - 9*t)/2, sqrt(3) = (11*t - t^3)/2, hence
\\ d = (3*sqrt(2) - sqrt(2)*sqrt(3))/4 = (3*t^3 - t^2 - 27*t + 5)/8 (reduced mod K), and
\\ (sqrt(3) - 1)/4 = (-t^3 + 11*t - 2)/8, (3 - sqrt(3))/4 = (t^3 - 11*t + 6)/8,
\\ (5 - sqrt(3))/4 = (t^3 - 11*t + 10)/8, (3 - sqrt(3))/2 = (t^3 - 11*t + 6)/4.
\\ Points: 1 = B, 2 = L, 3 = R, 4 = U.
\\ given: the coordinates rounded to 30 decimals (gp: round(v * 10^30) at \p 100).
\\ A value spanning several lines is wrapped in { } (gp file syntax).
\\ Coordinates file (provenance): tests/data/atlas-checker/n4-diamond-sqrt2.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n4-diamond-sqrt2"; n = 4;
P = 16*x^4 - 48*x^2 + 9;
d_low = 448/1000; d_high = 449/1000;
K = t^4 - 10*t^2 + 1;
t_low = 3146/1000; t_high = 3147/1000;
d_in_K = (3*t^3 - t^2 - 27*t + 5)/8;
sqrt3_in_K = (11*t - t^3)/2;
{points = [[1/2, 0],
           [(-t^3 + 11*t - 2)/8, (t^3 - 11*t + 6)/8],
           [(t^3 - 11*t + 10)/8, (t^3 - 11*t + 6)/8],
           [1/2, (t^3 - 11*t + 6)/4]];}
rattlers = [];
bonds = [[1, 2], [1, 3], [2, 4], [3, 4], [1, -1], [2, -2], [3, -3]];
{given = [
  [500000000000000000000000000000/10^30, 0/10^30],
  [183012701892219323381861585376/10^30, 316987298107780676618138414624/10^30],
  [816987298107780676618138414624/10^30, 316987298107780676618138414624/10^30],
  [500000000000000000000000000000/10^30, 633974596215561353236276829247/10^30]];}
given_tolerance = 10^-25;
claims = ["existence"];
