\\ Exact certificate (format 1) claiming "strict-local-optimum", written by hand for the independent
\\ checker's tests (not by tripack).
\\ n = 6: Delta(3), the corners and the side midpoints, d = 1/2; the configuration of
\\ ../n6_delta3.gp (derivation there; K = t^2 - 3/4, t0 = sqrt(3)/2, sqrt3_in_K = 2*t).
\\ Rigidity: 6 held disks, 12 coordinates, 18 bonds; the corners are pinned by their wall rows, each
\\ midpoint by its wall row (normal to its side) and its pair rows along the side: rank 12 (gp
\\ matrank over K).
\\ Stress: with gp from G over K (checker/README.md): matker(G~) has dimension 6 (18 - 12); the
\\ kernel element whose 9 pair entries are 1 (matinverseimage) has entry t = sqrt(3)/2 on the three
\\ bottom-wall bonds and t/2 = sqrt(3)/4 on the six left- and right-wall bonds.
\\ By hand (s = sqrt 3, wall rows (0, 1), (s, -1), (-s, -1)): at the bottom midpoint 2 = (1/2, 0) the
\\ pair rows x2 - x1, x2 - x3, x2 - x4, x2 - x5 = (1/2, 0), (-1/2, 0), (1/4, -s/4), (-1/4, -s/4) sum
\\ to (0, -s/2), balanced by the bottom wall with s/2; at corner 1 the pair rows (-1/2, 0) and
\\ (-1/4, -s/4) sum to (-3/4, -s/4), balanced by (0, 1)*s/2 + (s, -1)*s/4 = (3/4, s/4); at the
\\ left midpoint 4 the pair rows sum to (-3/4, s/4), balanced by (s, -1)*s/4; at the apex 6 they sum
\\ to (0, s/2), balanced by (s, -1)*s/4 + (-s, -1)*s/4 = (0, -s/2). The others by symmetry.
\\ Coordinates file (provenance): tests/data/atlas-checker/n6-delta3-slo.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n6-delta3-slo"; n = 6;
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
stress = [1, 1, 1, 1, 1, 1, 1, 1, 1, t, t, t, t/2, t/2, t/2, t/2, t/2, t/2];
{given = [
  [0/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [250000000000000000000000000000/10^30, 433012701892219323381861585376/10^30],
  [750000000000000000000000000000/10^30, 433012701892219323381861585376/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30]];}
given_tolerance = 10^-25;
claims = ["existence", "strict-local-optimum"];
