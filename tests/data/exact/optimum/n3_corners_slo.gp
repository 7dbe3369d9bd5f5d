\\ Exact certificate (format 1) claiming "strict-local-optimum", written by hand for the independent
\\ checker's tests (not by tripack).
\\ n = 3: the three corners of the unit triangle, d = 1; the configuration of ../n3_corners.gp
\\ (derivation of the points, d, K and given there) plus a stress.
\\ Rigidity: 3 held disks, 6 coordinates, 9 bonds. Each corner lies on two sides whose normals are
\\ independent, so its two wall rows alone pin it: G is injective (rank 6; gp matrank over
\\ Q[t]/(K)). The three pair bonds are not needed for that, but they carry the stress.
\\ Stress (one entry per bond, in the order of bonds): worked out with gp from the bond-opening
\\ matrix G of checker/README.md over K (entries Mod(., t^2 - 3)): matker(G~) has dimension 3
\\ (9 bonds - rank 6), and the kernel element whose three pair entries are 1 (matinverseimage) is
\\ [1, 1, 1, t, t/2, t, t/2, t/2, t/2], all positive at t0 = sqrt(3).
\\ By hand at corner 1 = (0,0): its pair rows give (x1 - x2) + (x1 - x3) = (-1, 0) + (-1/2, -sqrt3/2)
\\ = (-3/2, -sqrt3/2); its wall rows (0, 1) (bottom) and (sqrt3, -1) (left) with stresses sqrt3 and
\\ sqrt3/2 give (3/2, sqrt3 - sqrt3/2) = (3/2, sqrt3/2): the sum is 0. Corners 2 and 3 are mirror
\\ images / rotations of corner 1.
\\ Coordinates file (provenance): tests/data/atlas-checker/n3-corners-slo.txt, the given points in its 30-decimal
\\ format; check with checker/check_exact.sh --atlas tests/data/atlas-checker.
cert_format = 1;
label = "n3-corners-slo"; n = 3;
P = x - 1;
d_low = 9/10; d_high = 11/10;
K = t^2 - 3;
t_low = 1732/1000; t_high = 1733/1000;
d_in_K = 1;
sqrt3_in_K = t;
points = [[0, 0], [1, 0], [1/2, t/2]];
rattlers = [];
bonds = [[1, 2], [1, 3], [2, 3], [1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3]];
stress = [1, 1, 1, t, t/2, t, t/2, t/2, t/2];
{given = [
  [0/10^30, 0/10^30],
  [1000000000000000000000000000000/10^30, 0/10^30],
  [500000000000000000000000000000/10^30, 866025403784438646763723170753/10^30]];}
given_tolerance = 10^-25;
claims = ["existence", "strict-local-optimum"];
