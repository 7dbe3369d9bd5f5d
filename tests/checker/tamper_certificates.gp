\\ tamper_certificates.gp -- builds the tampered (and a few valid) certificates that
\\ tests/checker/exact_checker_test.sh runs through checker/check_exact.sh.
\\
\\ Usage: ROOT=<repository> OUT=<empty directory> gp -q -f tests/checker/tamper_certificates.gp < /dev/null
\\
\\ For every case it writes OUT/<case>/exact/<label>.gp and the coordinate file
\\ OUT/<case>/atlas/<label>.txt (the atlas format; a format-1 certificate finds it at
\\ <its dir>/../atlas/<label>.txt, a format-2 one names "../atlas/<label>.txt"), and one line
\\     <case>|<expectations>|<certificate path>|<description>
\\ in OUT/manifest.txt. Expectations, comma-separated: accept, accept-slo (both claims), reject,
\\ fail:CHECK, pass:CHECK, skip:CHECK (a line "FAIL CHECK:", "PASS CHECK:", "SKIP CHECK:" must be
\\ printed), note:TEXT (a line "NOTE TEXT..." must be printed), float300 (see below).
\\
\\ This is test code, not the checker: it loads its sources (data/exact/t10a.gp, t11a.gp and the
\\ hand-made certificates of tests/data/exact, all trusted files of this repository) with read().
\\
\\ The "huge C" disguise (the referee's attack on the old checker): an element A of K written as
\\ A + C*K(t) with a huge integer C is the same element of K, so every exact identity still holds,
\\ but evaluating it at a 300-digit approximation of t0 *as written* gives A(t0) plus noise whose
\\ sign and size the author chooses through C. For every disguised case ("float300") this
\\ generator searches C until the old checker's floating-point rules (300 digits, margins 1e-150:
\\ tg_old below, a transcription of them) accept the certificate, and stops with an error if it
\\ cannot; the new checker must reject it all the same.

default(debugmem, 0);
tg_root = getenv("ROOT"); tg_out = getenv("OUT");
if(type(tg_root) != "t_STR" || type(tg_out) != "t_STR", error("set ROOT and OUT"));
{tg_names = ["cert_format", "coordinates_file", "label", "n", "P", "d_low", "d_high", "K", "t_low", "t_high", \
  "d_in_K", "sqrt3_in_K", "points", "rattlers", "bonds", "given", "given_tolerance", "stress", "claims"];}
tg_ncases = 0; tg_nfooled = 0;

\\ ---------------------------------------------------------------------------------------------
\\ loading and writing certificates

\\ a certificate of this repository as a Map name -> value (read() of a trusted file)
tg_load(f) =
{
  my(R = Map(), v);
  foreach(tg_names, s, eval(Str(s, " = '", s)));
  read(f);
  foreach(tg_names, s, v = eval(s); if(!(type(v) == "t_POL" && v == eval(Str("'", s))), mapput(R, s, v)));
  R;
}
tg_get(R, s) = mapget(R, s);
tg_set(R, s, v) = mapput(R, s, v); R;
tg_del(R, s) = if(mapisdefined(R, s), mapdelete(R, s)); R;

{tg_val(v) = if(type(v) == "t_STR", Str("\"", v, "\""),
               type(v) == "t_VEC", Str("[", strjoin(apply(tg_val, v), ", "), "]"),
               Str(v));}
\\ write R in tripack's layout
tg_write(path, R) =
{
  my(L = List(["\\\\ tampered or hand-made certificate written by tests/checker/tamper_certificates.gp"]), v, s);
  foreach(tg_names, s,
    if(!mapisdefined(R, s), next);
    v = mapget(R, s);
    if(type(v) == "t_VEC" && #v > 0 && (s == "points" || s == "given" || s == "stress"),
      listput(L, Str("{", s, " = [\n  ", strjoin(apply(tg_val, v), ",\n  "), "];}")),
      listput(L, Str(s, " = ", tg_val(v), ";"))));
  tg_writefile(path, strjoin(Vec(L), "\n"));
}
tg_writefile(path, text) = system(Str("mkdir -p \"", tg_dirname(path), "\"")); write(path, text);
tg_dirname(f) = my(v = Vecsmall(f), k = 0); for(i = 1, #v, if(v[i] == 47, k = i)); Strchr(v[1 .. k - 1]);

tg_dec30(N) = my(a = abs(N), f = Str(a % 10^30)); while(#f < 30, f = Str("0", f)); Str(if(N < 0, "-", ""), a \ 10^30, ".", f);
\\ the atlas coordinate file of R (its given points must be multiples of 10^-30); dline: "# d: ..."
tg_atlas(path, R, dline) =
{
  my(G = tg_get(R, "given"), L);
  L = [Str("# written by tests/checker/tamper_certificates.gp"), Str("# n: ", #G), Str("# label: ", tg_get(R, "label")), dline];
  L = concat(L, vector(#G, i, Str(tg_dec30(G[i][1] * 10^30), " ", tg_dec30(G[i][2] * 10^30))));
  foreach(G, g, foreach(g, c, if(denominator(c * 10^30) != 1, error("given not on the 10^-30 grid"))));
  tg_writefile(path, strjoin(L, "\n"));
}
tg_dline_of(atlasfile) = my(L = readstr(atlasfile)); for(i = 1, #L, if(#L[i] > 5 && Vecsmall(L[i])[1 .. 5] == Vecsmall("# d: "), return(L[i]))); error("no # d: line");
tg_dline_calc(R) = my(t0, d); localprec(200); t0 = polrootsreal(tg_get(R, "K"), [tg_get(R, "t_low"), tg_get(R, "t_high")])[1]; \
  d = subst(tg_get(R, "d_in_K"), 't, t0); Str("# d: ", tg_dec30(round(d * 10^30)));
\\ given points: the exact points rounded to 30 decimals
tg_given30(R) =
{
  my(t0, P = tg_get(R, "points"));
  localprec(200); t0 = polrootsreal(tg_get(R, "K"), [tg_get(R, "t_low"), tg_get(R, "t_high")])[1];
  vector(#P, i, vector(2, k, my(c = P[i][k]); round(if(type(c) == "t_POL", subst(c, 't, t0), c) * 10^30) / 10^30));
}

\\ one case: format 1 (and with f2 = 1 also a format-2 copy, case name <name>-f2)
tg_case(name, expect, desc, R, dline, f2 = 0) =
{
  my(lab = tg_get(R, "label"), dir = Str(tg_out, "/", name), path);
  path = Str(dir, "/exact/", lab, ".gp");
  R = tg_set(R, "cert_format", 1); R = tg_del(R, "coordinates_file");
  tg_write(path, R);
  tg_atlas(Str(dir, "/atlas/", lab, ".txt"), R, dline);
  write(Str(tg_out, "/manifest.txt"), Str(name, "|", expect, "|", path, "|", desc));
  tg_ncases++;
  if(f2,
    my(R2 = tg_set(tg_set(R, "cert_format", 2), "coordinates_file", Str("../atlas/", lab, ".txt")), dir2 = Str(tg_out, "/", name, "-f2"), p2);
    p2 = Str(dir2, "/exact/", lab, ".gp");
    tg_write(p2, R2);
    tg_atlas(Str(dir2, "/atlas/", lab, ".txt"), R2, dline);
    write(Str(tg_out, "/manifest.txt"), Str(name, "-f2|", expect, "|", p2, "|", desc, " (format 2)"));
    tg_ncases++);
}

\\ ---------------------------------------------------------------------------------------------
\\ the old checker's floating-point rules (checker/check_exact.gp before this change): t0 from
\\ polrootsreal at 300 digits, every coordinate, d, sqrt3 and stress entry evaluated AS WRITTEN at
\\ t0, strict inequalities accepted with a margin > 1e-150. Returns [ok, why].

tg_t0f(R) = localprec(300); polrootsreal(tg_get(R, "K"), [tg_get(R, "t_low"), tg_get(R, "t_high")])[1];
tg_ev(v, t0) = if(type(v) == "t_POL", subst(v, 't, t0) * 1., v * 1.);

tg_old(R) =
{
  my(eps = 10^-150, t0, d0, P = tg_get(R, "P"), dl = tg_get(R, "d_low"), dh = tg_get(R, "d_high"), pts = tg_get(R, "points"),
     bonds = tg_get(R, "bonds"), G = tg_get(R, "given"), tol = tg_get(R, "given_tolerance"), n = #pts, X, Y, M, W, s, rp, S, v, m,
     slo = (#select(c -> c == "strict-local-optimum", tg_get(R, "claims")) > 0));
  localprec(300);
  t0 = tg_t0f(R);
  d0 = tg_ev(tg_get(R, "d_in_K"), t0);
  if(!(d0 >= dl && d0 <= dh), return([0, "embedding: d0 not in [d_low, d_high]"]));
  rp = polrootsreal(P, [dl, dh]); if(#rp != 1 || abs(rp[1] - d0) > eps, return([0, "embedding: d0 is not the root of P"]));
  if(d0 <= eps, return([0, "embedding: d0 <= 0"]));
  s = tg_ev(tg_get(R, "sqrt3_in_K"), t0); if(!(s > 0 && abs(s - sqrt(3)) < eps), return([0, "sqrt3-sign"]));
  X = vector(n, i, tg_ev(pts[i][1], t0)); Y = vector(n, i, tg_ev(pts[i][2], t0));
  for(i = 1, n, if(max(abs(X[i] - G[i][1]), abs(Y[i] - G[i][2])) > tol, return([0, Str("given-distance at ", i)])));
  M = matrix(n, n); W = matrix(n, 3);
  foreach(bonds, b, if(b[2] > 0, M[b[1], b[2]] = 1, W[b[1], -b[2]] = 1));
  for(i = 1, n - 1, for(j = i + 1, n, if(!M[i, j] && sqrt((X[i] - X[j])^2 + (Y[i] - Y[j])^2) - d0 <= eps, return([0, Str("separation at ", [i, j])]))));
  for(i = 1, n, for(w = 1, 3, if(!W[i, w],
    v = if(w == 1, Y[i], w == 2, (sqrt(3) * X[i] - Y[i]) / 2, (sqrt(3) * (1 - X[i]) - Y[i]) / 2);
    if(v <= eps, return([0, Str("walls at ", [i, -w])])))));
  if(slo,
    S = apply(e -> tg_ev(e, t0), tg_get(R, "stress")); m = vecmax(apply(abs, S));
    for(b = 1, #S, if(S[b] / m <= eps, return([0, Str("stress-positive at ", b)]))));
  [1, "the old floating-point rules accept"];
}

\\ the disguise: a candidate A + C*K, C = m * 10^e, whose value as written at t0 (300 digits)
\\ satisfies pred(value); searched over e and small m (polrootsreal returns t0 to far more than
\\ 300 digits, ~900 for t10a, so C must be about 10^(digits of t0 - 40) to move a value by 1e-40)
tg_disguise(R, A, pred) =
{
  my(K = tg_get(R, "K"), t0 = tg_t0f(R), c, v);
  localprec(300);
  forstep(e = 60, 4000, 1, foreach([1, -1, 2, -2, 3, -3, 5, -5, 7, -7, 11, -11], m,
    c = A + m * 10^e * K;
    v = tg_ev(c, t0);
    if(pred(v), return(c))));
  error("no disguise found");
}
\\ require that the old floating-point rules accept R (the disguise works) and count it
tg_fooled(R, what) = my(r = tg_old(R)); if(!r[1], error(Str(what, ": the disguise does not fool the floating-point rules: ", r[2]))); tg_nfooled++; 1;

\\ ---------------------------------------------------------------------------------------------
\\ exact helpers over K

tg_red(R, e) = my(K = tg_get(R, "K")); if(type(e) == "t_POL", my(r = lift(Mod(e, K))); if(type(r) == "t_POL" && poldegree(r) <= 0, polcoef(r, 0), r), e);
\\ the bond-opening matrix G over K (rows in bond order, 2 columns per held disk)
tg_G(R) =
{
  my(K = tg_get(R, "K"), pts = tg_get(R, "points"), bonds = tg_get(R, "bonds"), Rt = Set(tg_get(R, "rattlers")), H, col, G, s3 = Mod(tg_get(R, "sqrt3_in_K"), K));
  H = [i | i <- [1 .. #pts], !setsearch(Rt, i)]; col = vector(#pts); for(k = 1, #H, col[H[k]] = k);
  G = matrix(#bonds, 2 * #H, r, c, Mod(0, K));
  for(b = 1, #bonds, my(i = bonds[b][1], j = bonds[b][2], ci = 2 * col[i] - 1, cj, dx, dy);
    if(j > 0, cj = 2 * col[j] - 1; dx = Mod(pts[i][1] - pts[j][1], K); dy = Mod(pts[i][2] - pts[j][2], K);
      G[b, ci] = dx; G[b, ci + 1] = dy; G[b, cj] = -dx; G[b, cj + 1] = -dy,
      j == -1, G[b, ci + 1] = Mod(1, K), j == -2, G[b, ci] = s3; G[b, ci + 1] = Mod(-1, K), G[b, ci] = -s3; G[b, ci + 1] = Mod(-1, K)));
  G;
}
\\ R's stress made 0 on bond b0 by the least-norm correction on the other bonds (exact over K):
\\ returns the new stress (entry b0 = 0, still balanced) or 0
tg_stress_without(R, b0) =
{
  my(K = tg_get(R, "K"), s = tg_get(R, "stress"), G = tg_G(R), B = #s, idx, Gr, v, c, out);
  idx = [b | b <- [1 .. B], b != b0];
  Gr = matrix(#idx, #G, r, k, G[idx[r], k]);
  v = Mod(s[b0], K) * G[b0, ]~;                       \\ the force the removed entry carried
  c = iferr(Gr * matsolve(Gr~ * Gr, v), E, return(0)); \\ Gr^T c = v, c of least norm
  out = vector(B);
  for(r = 1, #idx, out[idx[r]] = lift(Mod(s[idx[r]], K) + c[r]));
  out[b0] = 0;
  out;
}
tg_positive(R, s) = my(t0 = tg_t0f(R)); localprec(300); #select(e -> tg_ev(e, t0) <= 10^-20, s) == 0;
tg_lifted(v) = apply(e -> if(type(e) == "t_POLMOD", lift(e), e), v);

\\ ---------------------------------------------------------------------------------------------
\\ sources

F = (s) -> Str(tg_root, "/tests/data/exact/", s, ".gp");
tg_fixture(s) = tg_load(F(s));
tg_real(l) = tg_load(Str(tg_root, "/data/exact/", l, ".gp"));
tg_real_dline(l) = tg_dline_of(Str(tg_root, "/data/atlas/", l, ".txt"));
\\ a fixture-based case: the atlas file is made from the (possibly changed) given points
fx(name, src, expect, desc, f) = my(R = tg_fixture(src), dl = tg_dline_calc(R)); tg_case(name, expect, desc, f(R), dl);

\\ =============================================================================================
\\ 1. the checks on hand-made certificates (tests/data/exact): one tampering each
\\ =============================================================================================

fx("P_coef", "n4_centre", "reject,fail:d-identity", "P coefficient changed", R -> tg_set(R, "P", 3*x^2 - 2));
fx("P_coef4", "n4_diamond_sqrt2", "reject,fail:d-identity", "P coefficient changed, degree 4", R -> tg_set(R, "P", 16*x^4 - 48*x^2 + 7));
fx("P_red", "n4_centre", "reject,fail:P-irreducible", "P reducible", R -> tg_set(R, "P", (3*x^2 - 1)*(x - 5)));
fx("P_prim", "n4_centre", "reject,fail:P-primitive", "P not primitive", R -> tg_set(R, "P", 6*x^2 - 2));
fx("P_int", "n4_centre", "reject,fail:P-integral", "P with a rational coefficient", R -> tg_set(R, "P", x^2 - 1/3));
{fx("bond_pair", "n6_delta3", "reject,fail:separation", "disk bond [4, 5] removed: an unlisted contact",
  R -> tg_set(R, "bonds", [b | b <- tg_get(R, "bonds"), b != [4, 5]]));}
fx("bond_pair2", "n5_square", "reject,fail:separation", "disk bond [3, 5] removed", R -> tg_set(R, "bonds", [b | b <- tg_get(R, "bonds"), b != [3, 5]]));
{fx("bond_wall", "n3_corners", "reject,fail:walls", "wall bond [3, -3] removed: a point on a wall, unlisted",
  R -> tg_set(R, "bonds", [b | b <- tg_get(R, "bonds"), b != [3, -3]]));}
{fx("move", "n5_square", "reject,fail:bond-identities", "point moved by 1e-30 (within given_tolerance)",
  R -> my(p = tg_get(R, "points")); p[5] = [1/2, (t + 3)/4 + 1/10^30]; tg_set(R, "points", p));}
{fx("move4", "n4_diamond_sqrt2", "reject,fail:bond-identities", "point moved in the degree-4 field",
  R -> my(p = tg_get(R, "points")); p[4] = [1/2 + 1/10^40, (t^3 - 11*t + 6)/4]; tg_set(R, "points", p));}
{fx("given_far", "n4_centre", "reject,fail:given-distance,pass:provenance", "given point moved by 1e-20 (and its coordinate file with it)",
  R -> my(g = tg_get(R, "given")); g[4][2] += 1/10^20; tg_set(R, "given", g));}
{fx("root_other", "n4_diamond_sqrt2", "reject,fail:embedding", "interval around another root of P",
  R -> tg_set(tg_set(R, "d_low", 1673/1000), "d_high", 1674/1000));}
{fx("root_neg", "n4_centre", "reject,fail:embedding", "interval around the negative root of P",
  R -> tg_set(tg_set(R, "d_low", -578/1000), "d_high", -577/1000));}
fx("root_none", "n4_centre", "reject,fail:P-interval", "interval containing no root of P", R -> tg_set(tg_set(R, "d_low", 1/10), "d_high", 2/10));
fx("root_two", "n4_centre", "reject,fail:P-interval", "interval containing two roots of P", R -> tg_set(tg_set(R, "d_low", -1), "d_high", 1));
{fx("K_other", "n4_centre", "reject,fail:sqrt3-sign", "the other embedding of K (t0 = -sqrt 3)",
  R -> tg_set(tg_set(R, "t_low", -1733/1000), "t_high", -1732/1000));}
fx("K_none", "n5_square", "reject,fail:K-interval", "K interval without a root", R -> tg_set(tg_set(R, "t_low", 1/2), "t_high", 1));
fx("K_red", "n3_corners", "reject,fail:K-irreducible", "K reducible", R -> tg_set(R, "K", t^2 - 4));
fx("rattler_pair", "n8_rattler", "reject,fail:rattler-bonds", "rattler in a disk bond", R -> tg_set(R, "bonds", concat(tg_get(R, "bonds"), [[5, 8]])));
fx("rattler_wall", "n8_rattler", "reject,fail:rattler-bonds", "rattler in a wall bond", R -> tg_set(R, "bonds", concat(tg_get(R, "bonds"), [[8, -1]])));
{fx("rattler_K", "n8_rattler", "reject,fail:coordinates", "rattler with a coordinate in K",
  R -> my(p = tg_get(R, "points")); p[8] = [1/2, t/8]; tg_set(R, "points", p));}
{fx("rattler_out", "n8_rattler", "reject,fail:walls", "rattler outside the triangle",
  R -> my(p = tg_get(R, "points"), g = tg_get(R, "given")); p[8] = [1/2, -1/5]; g[8] = [1/2, -1/5]; tg_set(tg_set(R, "points", p), "given", g));}
fx("missing", "n3_corners", "reject,fail:variables", "d_in_K missing", R -> tg_del(R, "d_in_K"));
fx("dup_bond", "n4_centre", "reject,fail:bond-duplicates", "duplicate bond", R -> tg_set(R, "bonds", concat(tg_get(R, "bonds"), [[1, 4]])));
fx("bond_index", "n4_centre", "reject,fail:bond-indices", "bond index out of range", R -> tg_set(R, "bonds", concat(tg_get(R, "bonds"), [[4, 5]])));
{fx("no_pair", "n3_corners", "reject,fail:d-attained", "no disk bond at all",
  R -> tg_set(R, "bonds", [[1, -1], [1, -2], [2, -1], [2, -3], [3, -2], [3, -3]]));}
fx("claims", "n3_corners", "reject,fail:claims", "claims without existence", R -> tg_set(R, "claims", ["strict-local-optimum"]));
{fx("claim_unknown", "n4_centre", "reject,fail:claims", "an unknown claim is rejected, not passed with a note",
  R -> tg_set(R, "claims", ["existence", "global-optimum"]));}

\\ statement (II)
{fx("slo_tiny", "optimum/n3_corners_slo", "accept-slo", "a balanced stress with a pair entry 1e-200 > 0 (exact signs: no margin)",
  R -> tg_set(R, "stress", [1/10^200, 1, 1, (2 + 1/10^200)/3*t, (1 + 2/10^200)/6*t, (2 + 1/10^200)/3*t, (1 + 2/10^200)/6*t, t/2, t/2]));}
{fx("slo_unreduced", "optimum/n4_centre_slo", "accept-slo", "a stress entry written with a multiple of K added (the same element of K)",
  R -> my(s = tg_get(R, "stress")); s[9] = (11*t - t^3)/12 + (t^4 - 10*t^2 + 1)*(t + 5); tg_set(R, "stress", s));}
{fx("slo_neg", "optimum/n3_corners_slo", "reject,fail:stress-positive", "a stress entry negated",
  R -> my(s = tg_get(R, "stress")); s[1] = -1; tg_set(R, "stress", s));}
{fx("slo_negall", "optimum/n6_delta3_slo", "reject,fail:stress-positive,pass:stress-balance,pass:rigidity", "the whole stress negated (still balanced)",
  R -> tg_set(R, "stress", -tg_get(R, "stress")));}
{fx("slo_change", "optimum/n3_corners_slo", "reject,fail:stress-balance,pass:stress-positive,pass:rigidity", "a stress entry changed by 1e-30",
  R -> my(s = tg_get(R, "stress")); s[4] = t + 1/10^30; tg_set(R, "stress", s));}
{fx("slo_change4", "optimum/n4_centre_slo", "reject,fail:stress-balance,pass:stress-positive,pass:rigidity", "a stress entry changed by 1/10, degree-4 field",
  R -> my(s = tg_get(R, "stress")); s[9] = (11*t - t^3)/12 + (t^4 - 10*t^2 + 1) + 1/10; tg_set(R, "stress", s));}
{fx("slo_swap", "optimum/n6_delta3_slo", "reject,fail:stress-balance", "a wall stress moved to another wall",
  R -> my(s = tg_get(R, "stress")); s[10] = t/2; s[13] = t; tg_set(R, "stress", s));}
fx("slo_none", "optimum/n3_corners_slo", "reject,fail:stress-format", "claim without a stress variable", R -> tg_del(R, "stress"));
{fx("slo_none2", "n4_centre", "reject,fail:stress-format", "claim added to a certificate without stress",
  R -> tg_set(R, "claims", ["existence", "strict-local-optimum"]));}
fx("slo_len", "optimum/n3_corners_slo", "reject,fail:stress-format", "stress with too few entries", R -> tg_set(R, "stress", [1, 1, 1]));
{fx("slo_type", "optimum/n3_corners_slo", "reject,fail:stress-format", "stress entry not in K",
  R -> my(s = tg_get(R, "stress")); s[2] = x + 1; tg_set(R, "stress", s));}
{fx("slo_bond", "optimum/n6_delta3_slo", "reject,fail:separation,pass:stress-format,skip:stress-balance,skip:stress-positive,skip:rigidity",
  "bond [4, 5] and its stress removed: existence fails, statement II skipped",
  R -> my(b = tg_get(R, "bonds"), s = tg_get(R, "stress")); tg_set(tg_set(R, "bonds", concat(b[1 .. 6], b[8 .. 18])), "stress", concat(s[1 .. 6], s[8 .. 18])));}
{fx("slo_lone", "n8_rattler", "reject,fail:rigidity", "held disk without a bond (the rattler declared held)",
  R -> tg_set(tg_set(tg_set(R, "rattlers", []), "claims", ["existence", "strict-local-optimum"]), "stress", vector(17, b, 1)));}
{fx("slo_noclaim", "optimum/n3_corners_slo", "accept,note:stress is assigned but", "stress without the claim: noted, not checked",
  R -> my(s = tg_get(R, "stress")); s[1] = -1; tg_set(tg_set(R, "claims", ["existence"]), "stress", s));}

\\ =============================================================================================
\\ 2. the referee's wrong certificates (a)-(e), plain and with the "huge C" disguise, from real
\\    certificates of data/exact (t10a, t11a) and hand-made configurations; format 1 and 2
\\ =============================================================================================

\\ valid, written unreduced: every coordinate and stress entry of t10a plus a huge multiple of K
{
  my(R = tg_real("t10a"), K = tg_get(R, "K"), C = 10^200 + 12345, p = tg_get(R, "points"), s = tg_get(R, "stress"));
  p = vector(#p, i, vector(2, k, p[i][k] + (C + i + k) * K));
  s = vector(#s, b, s[b] + (C - b) * K);
  R = tg_set(tg_set(R, "points", p), "stress", s);
  R = tg_set(R, "d_in_K", tg_get(R, "d_in_K") + 7 * C * K);
  tg_case("valid_unreduced", "accept-slo", "t10a with every element of K written as p + C*K(t), C ~ 1e200 (reduced mod K, accepted)", R, tg_real_dline("t10a"), 1);
  tg_case("valid_t10a", "accept-slo", "t10a as tripack wrote it, rewritten", tg_real("t10a"), tg_real_dline("t10a"), 1);
  tg_case("valid_t11a", "accept-slo", "t11a (a rattler), rewritten", tg_real("t11a"), tg_real_dline("t11a"), 1);
}

\\ (a) a rattler at distance d - 1e-40 from a disk
tg_rattler_case(name, R, dline, r, desc) =
{
  my(pts = tg_get(R, "points"), K = tg_get(R, "K"), t0, X, Y, d, j = 0, best = oo, u, q, g, disg, Rd);
  localprec(300);
  t0 = tg_t0f(R); d = tg_ev(tg_get(R, "d_in_K"), t0);
  X = vector(#pts, i, tg_ev(pts[i][1], t0)); Y = vector(#pts, i, tg_ev(pts[i][2], t0));
  for(i = 1, #pts, if(i != r && !setsearch(Set(tg_get(R, "rattlers")), i),
    my(dd = sqrt((X[i] - X[r])^2 + (Y[i] - Y[r])^2)); if(dd < best, best = dd; j = i)));
  u = [X[r] - X[j], Y[r] - Y[j]] / best;
  q = vector(2, k, round(([X[j], Y[j]][k] + (d - 10^-40) * u[k]) * 10^60) / 10^60);
  pts[r] = q; g = tg_get(R, "given"); g[r] = vector(2, k, round(q[k] * 10^30) / 10^30);
  R = tg_set(tg_set(R, "points", pts), "given", g);
  tg_case(Str(name, "_plain"), "reject,fail:separation,pass:provenance", Str(desc, ": rattler ", r, " at distance d - 1e-40 from disk ", j), R, dline, 1);
  \\ disguise: disk j's coordinate moved away from the rattler in floating point only
  my(k = if(abs(u[1]) > abs(u[2]), 1, 2), A = pts[j][k], old = [X[j], Y[j]][k]);
  disg = tg_disguise(R, A, v -> my(P2 = [X[j], Y[j]]); P2[k] = v;
    abs(v - old) < 10^-30 && sqrt((P2[1] - q[1])^2 + (P2[2] - q[2])^2) - d > 10^-140);
  pts[j][k] = disg; Rd = tg_set(R, "points", pts);
  tg_fooled(Rd, name);
  tg_case(Str(name, "_C"), "reject,fail:separation,pass:bond-identities,pass:provenance,float300",
    Str(desc, ": rattler ", r, " at distance d - 1e-40 from disk ", j, ", disk ", j, " disguised with a huge C*K(t)"), Rd, dline, 1);
}
tg_rattler_case("a_t11a", tg_real("t11a"), tg_real_dline("t11a"), 2, "(a) t11a");
{ my(R = tg_fixture("n8_rattler")); tg_rattler_case("a_n8", R, tg_dline_calc(R), 8, "(a) n8-rattler"); }

\\ (b) a bond deleted: the listed contacts are not all the contacts
\\ pair bond [i, j] of R deleted; the disguise moves x_i or y_i away from j in floating point
tg_bond_case(name, R, dline, bij, desc, stress) =
{
  my(pts = tg_get(R, "points"), t0, X, Y, d, i = bij[1], j = bij[2], k, A, old, disg, Rd, b = tg_get(R, "bonds"));
  localprec(300);
  t0 = tg_t0f(R); d = tg_ev(tg_get(R, "d_in_K"), t0);
  X = vector(#pts, m, tg_ev(pts[m][1], t0)); Y = vector(#pts, m, tg_ev(pts[m][2], t0));
  if(stress === 0,
    R = tg_set(tg_del(R, "stress"), "claims", ["existence"]),
    R = tg_set(tg_set(R, "stress", [stress[m] | m <- [1 .. #b], b[m] != bij]), "claims", ["existence", "strict-local-optimum"]));
  R = tg_set(R, "bonds", [c | c <- b, c != bij]);
  tg_case(Str(name, "_plain"), "reject,fail:separation", Str(desc, ": bond ", bij, " deleted"), R, dline, 1);
  k = if(abs(X[i] - X[j]) > abs(Y[i] - Y[j]), 1, 2); A = pts[i][k]; old = [X[i], Y[i]][k];
  disg = tg_disguise(R, A, v -> my(P2 = [X[i], Y[i]]); P2[k] = v;
    abs(v - old) < 10^-30 && sqrt((P2[1] - X[j])^2 + (P2[2] - Y[j])^2) - d > 10^-140);
  pts[i][k] = disg; Rd = tg_set(R, "points", pts);
  tg_fooled(Rd, name);
  tg_case(Str(name, "_C"), Str("reject,fail:separation,pass:bond-identities,float300", if(stress === 0, "", ",skip:stress-positive")),
    Str(desc, ": bond ", bij, " deleted, point ", i, " disguised with a huge C*K(t)"), Rd, dline, 1);
}
tg_bond_case("b_t10a", tg_real("t10a"), tg_real_dline("t10a"), [1, 3], "(b) t10a", 0);
{ my(R = tg_fixture("n6_delta3")); tg_bond_case("b_n6", R, tg_dline_calc(R), [4, 5], "(b) n6-delta3", 0); }

\\ (b) with a wall bond: point on the bottom wall, its bond deleted, y disguised
{
  my(R = tg_real("t10a"), pts, Rd, dl = tg_real_dline("t10a"));
  R = tg_set(tg_del(R, "stress"), "claims", ["existence"]);
  R = tg_set(R, "bonds", [c | c <- tg_get(R, "bonds"), c != [3, -1]]);
  tg_case("b_wall_plain", "reject,fail:walls", "(b) t10a: wall bond [3, -1] deleted (point 3 is on the bottom)", R, dl, 1);
  pts = tg_get(R, "points");
  pts[3][2] = tg_disguise(R, pts[3][2], v -> v > 10^-140 && v < 10^-30);
  Rd = tg_set(R, "points", pts); tg_fooled(Rd, "b_wall");
  tg_case("b_wall_C", "reject,fail:walls,float300", "(b) t10a: wall bond [3, -1] deleted, y_3 = 0 disguised with a huge C*K(t)", Rd, dl, 1);
}

\\ (b) and (c) with an exact positive stress: the stress of t10a made 0 on one pair bond by an exact
\\ balanced correction on the others (searching a bond for which the rest stays positive)
{
  my(R = tg_real("t10a"), dl = tg_real_dline("t10a"), b = tg_get(R, "bonds"), s0 = 0, b0 = 0, s, Rc, Rd, t0, M);
  for(m = 1, #b, if(b[m][2] > 0, s = tg_stress_without(R, m);
    if(!(s === 0) && tg_positive(R, [s[k] | k <- [1 .. #s], k != m]), s0 = s; b0 = m; break)));
  if(b0 == 0, error("no bond of t10a whose stress can be moved to the others"));
  \\ (b) the bond deleted, with a positive balanced stress on the remaining bonds
  tg_bond_case("b_t10a_stress", R, dl, b[b0], "(b) t10a with an exact positive stress re-computed on the remaining bonds", s0);
  \\ (c) the bond kept, its stress entry exactly 0 (balanced, all others > 0)
  Rc = tg_set(R, "stress", s0);
  tg_case("c_t10a_plain", "reject,fail:stress-positive,pass:stress-balance,pass:rigidity", Str("(c) t10a: stress entry of bond ", b[b0], " is 0"), Rc, dl, 1);
  localprec(300); t0 = tg_t0f(R); M = vecmax(apply(e -> abs(tg_ev(e, t0)), s0));
  s = s0; s[b0] = tg_disguise(R, 0, v -> v / M > 10^-140);
  Rd = tg_set(R, "stress", s); tg_fooled(Rd, "c_t10a");
  tg_case("c_t10a_C", "reject,fail:stress-positive,pass:stress-balance,pass:rigidity,float300",
    Str("(c) t10a: stress entry of bond ", b[b0], " is 0 in K, written as a huge C*K(t)"), Rd, dl, 1);
}

\\ (d) a 3-disk configuration that is NOT a local optimum: an equilateral triangle of side d = 1/2
\\ in the corner (0,0); it can grow (disk 2 slides right, disk 3 up the left side), and its only
\\ balanced stresses have a negative entry; G is injective (rank 6)
tg_triangle(d, K, tl, th, s3, P, dl, dh, label) =
{
  my(R = Map());
  R = tg_set(R, "label", label); R = tg_set(R, "n", 3); R = tg_set(R, "P", P); R = tg_set(R, "d_low", dl); R = tg_set(R, "d_high", dh);
  R = tg_set(R, "K", K); R = tg_set(R, "t_low", tl); R = tg_set(R, "t_high", th); R = tg_set(R, "d_in_K", d); R = tg_set(R, "sqrt3_in_K", s3);
  R = tg_set(R, "points", [[0, 0], [d, 0], [d/2, lift(Mod(d * s3 / 2, K))]]);
  R = tg_set(R, "rattlers", []);
  R = tg_set(R, "bonds", [[1, 2], [1, 3], [2, 3], [1, -1], [1, -2], [2, -1], [3, -2]]);
  R = tg_set(R, "given_tolerance", 10^-25); R = tg_set(R, "claims", ["existence"]);
  R = tg_set(R, "given", tg_given30(R));
  R;
}
{
  my(R = tg_triangle(1/2, t^2 - 3, 1732/1000, 1733/1000, t, 2*x - 1, 49/100, 51/100, "n3-corner-triangle"), G, k, s, Rd, t0, M);
  G = tg_G(R);
  if(matrank(G) != 6, error("(d): G is not injective"));
  k = matker(G~); if(#k != 1, error("(d): the stress space is not 1-dimensional"));
  s = k[, 1]~; s = s / s[1]; s = apply(e -> tg_red(R, lift(e)), s);   \\ normalised: s_[1,2] = 1
  R = tg_set(tg_set(R, "claims", ["existence", "strict-local-optimum"]), "stress", s);
  tg_case("d_plain", "reject,fail:stress-positive,pass:stress-balance,pass:rigidity,pass:separation,pass:walls",
    Str("(d) n = 3 corner triangle of side 1/2 (not a local optimum), its balanced stress ", s, " has negative entries"), R, tg_dline_calc(R), 1);
  localprec(300); t0 = tg_t0f(R); M = vecmax(apply(e -> abs(tg_ev(e, t0)), s));
  s = vector(#s, b, if(tg_ev(s[b], t0) > 0, s[b], tg_disguise(R, s[b], v -> v / M > 10^-140)));
  Rd = tg_set(R, "stress", s); tg_fooled(Rd, "d");
  tg_case("d_C", "reject,fail:stress-positive,pass:stress-balance,pass:rigidity,float300",
    "(d) the same with every non-positive stress entry disguised with a huge C*K(t)", Rd, tg_dline_calc(R), 1);
}

\\ (e) P with two roots 2.8e-200 apart: d = 1/2 + sqrt(2)*10^-200 (the same corner triangle, side d,
\\ in K = Q(sqrt 2, sqrt 3) = Q[t]/(t^4 - 10 t^2 + 1), t0 = sqrt 2 + sqrt 3), P = the minimal
\\ polynomial of d, [d_low, d_high] = [1/4, 1/2] isolates the OTHER root 1/2 - sqrt(2)*10^-200
{
  my(K = t^4 - 10*t^2 + 1, s2 = (t^3 - 9*t)/2, s3 = (11*t - t^3)/2, d = 1/2 + s2 / 10^200, P, R, Rd, rp, t0);
  P = 10^400 * (2*x - 1)^2 - 8; P = P / content(P);
  R = tg_triangle(d, K, 3146/1000, 3147/1000, s3, P, 1/4, 1/2, "n3-close-roots");
  if(!polisirreducible(P) || polsturm(P, [1/4, 1/2]) != 1 || subst(P, 'x, Mod(d, K)) != 0, error("(e) construction"));
  tg_case("e_plain", "reject,fail:embedding,pass:P-interval,pass:d-identity",
    "(e) P with two roots 2.8e-200 apart, [d_low, d_high] isolating the root that is not d", R, tg_dline_calc(R), 1);
  localprec(300); rp = polrootsreal(P, [1/4, 1/2])[1];
  Rd = tg_set(R, "d_in_K", tg_disguise(R, d, v -> v >= 1/4 && v <= 1/2 && abs(v - rp) < 10^-160));
  tg_fooled(Rd, "e");
  tg_case("e_C", "reject,fail:embedding,pass:P-interval,pass:d-identity,float300",
    "(e) the same with d_in_K disguised with a huge C*K(t) so that it evaluates inside [d_low, d_high]", Rd, tg_dline_calc(R), 1);
}

print("tamper_certificates: ", tg_ncases, " certificates written (", tg_nfooled, " disguised cases verified to fool the 300-digit floating-point rules)");
quit(0);
