\\ Exact certificate in format 3, written by hand for the independent checker's tests (not by
\\ tripack): the configuration, bonds and stress of n6_delta3_slo.gp (derivations there), with the
\\ points and the stress written in the tower basis, x = d_in_K and s = sqrt3_in_K (docs/exact.md,
\\ "Certificates"): P = 2x - 1 has degree 1, so each is a + s*b with a, b rational. The
\\ checker maps them into K = Q[t]/(t^2 - 3/4), where s = 2t: s/4 = t/2 and s/2 = t, the format-1
\\ values of n6_delta3_slo.gp.
cert_format = 3;
coordinates_file = "../../atlas-checker/n6-delta3-slo.txt";
label = "n6-delta3-slo"; n = 6;
P = 2*x - 1;
d_low = 49/100; d_high = 51/100;
K = t^2 - 3/4;
t_low = 866/1000; t_high = 867/1000;
d_in_K = 1/2;
sqrt3_in_K = 2*t;
points = [[0, 0], [1/2, 0], [1, 0], [1/4, s/4], [3/4, s/4], [1/2, s/2]];
rattlers = [];
{bonds = [[1, 2], [2, 3], [1, 4], [2, 4], [2, 5], [3, 5], [4, 5], [4, 6], [5, 6],
          [1, -1], [2, -1], [3, -1], [1, -2], [4, -2], [6, -2], [3, -3], [5, -3], [6, -3]];}
stress = [1, 1, 1, 1, 1, 1, 1, 1, 1, s/2, s/2, s/2, s/4, s/4, s/4, s/4, s/4, s/4];
{given = [
  [0/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [250000000000000000000000000000/10^30, 433012701892219323381861585376/10^30],
  [750000000000000000000000000000/10^30, 433012701892219323381861585376/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30]];}
given_tolerance = 10^-25;
claims = ["existence", "strict-local-optimum"];
