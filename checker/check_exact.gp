\\ check_exact.gp -- independent checker for tripack exact certificates (format 1).
\\
\\ Written in PARI/GP only; shares no code with tripack (which writes certificates with
\\ FLINT/Arb). It re-checks statement (I), "existence": the stated points form a packing of n
\\ points in the unit triangle (0,0), (1,0), (1/2, sqrt(3)/2) whose minimum distance is d, every
\\ stated bond holding exactly. When the certificate also claims "strict-local-optimum"
\\ (statement II) and gives a stress (one entry per bond, an element of K), it checks that the
\\ stress balances exactly in K (G^T stress = 0), is positive at t0 (numerically), and that the
\\ bond-opening matrix G of the held disks has full column rank over K (exact, matrank over
\\ Q[t]/(K)). See checker/README.md for what is and is not proved.
\\
\\ Usage (normally through checker/check_exact.sh):
\\   CERT_FILE=cert.gp gp -q -f checker/check_exact.gp < /dev/null
\\ or   echo 'cert_file = "cert.gp"; read("checker/check_exact.gp")' | gp -q -f
\\ Exit status: 0 = ACCEPTED, 1 = REJECTED (including an unreadable file or a missing
\\ variable). Output: one "PASS name: detail" / "FAIL name: detail" line per check, "NOTE" and
\\ "SKIP" lines, and a final "certificate LABEL: ACCEPTED (existence)",
\\ "certificate LABEL: ACCEPTED (existence, strict-local-optimum)" or
\\ "certificate LABEL: REJECTED (k failures)".
\\
\\ Order matters in this file: the certificate is scanned and read FIRST, and every function
\\ and global of the checker is defined AFTER the read, so a certificate cannot replace them.
\\ Only ck_file and ck_scan (the loader and lexical safety scan) exist before the read.

default(debugmem, 0);
ck_file = if(type(cert_file) == "t_STR", cert_file, getenv("CERT_FILE"));
if(type(ck_file) != "t_STR" || ck_file == "", \
  print("certificate ?: REJECTED (no certificate file given: set CERT_FILE or cert_file)"); quit(1));
default(secure, 1);

\\ Loading the certificate. A certificate is a GP file as read by read(file): one statement
\\ per line, or several lines grouped in { }, "\\" and "/* */" comments. It is NOT loaded with
\\ read(): after a syntax error inside read(), gp 2.15 goes on executing the rest of the file in
\\ the caller's context. ck_scan instead applies gp's file rules itself (a newline outside { }
\\ ends a statement; comments removed; the braces dropped) and the result is eval'ed, where any
\\ error is caught cleanly.
\\ It is also a lexical safety scan: a format-1 certificate is data (assignments of numbers,
\\ strings, vectors and polynomials), so it must not call any built-in GP function (print, quit,
\\ read, system, install, eval, ...) except a few pure constructors, and must not contain a GP
\\ metacommand or a line continuation (a backslash outside a string or a \\ comment). Without
\\ this a certificate could print "ACCEPTED" and quit(0) by itself.
\\ Returns ["", text to eval], [reason, ""] when the file cannot be read, [reason, "unsafe"]
\\ when it is not safe.
ck_scan(f) =
{
  my(L, s, o, N, i, j, c, id, depth = 0, isal,
     allow = Set(["Mod", "Pol", "Polrev", "Vec", "Col", "Mat", "vector", "matrix", "concat"]));
  isal = (c -> (c >= 48 && c <= 57) || (c >= 65 && c <= 90) || (c >= 97 && c <= 122) || c == 95);
  L = iferr(readstr(f), E, return([Str("cannot read ", f, ": ", E), ""]));  \\ "" marks a read failure
  s = Vecsmall(strjoin(L, "\n")); N = #s; o = s; i = 1;
  while(i <= N,
    c = s[i];
    if(c == 34, \\ string literal: copied; skip to the closing quote, honouring backslash escapes
      i++; while(i <= N && s[i] != 34, if(s[i] == 92, i++); i++);
      if(i > N, return(["unterminated string", "unsafe"])); i++; next);
    if(c == 92, \\ backslash: only the comment \\ ... end of line is allowed
      if(i < N && s[i + 1] == 92, while(i <= N && s[i] != 10, o[i] = 32; i++); next);
      return([Str("backslash outside a string or \\\\ comment (metacommand, continuation or \\ operator) at byte ", i), "unsafe"]));
    if(c == 47 && i < N && s[i + 1] == 42, \\ /* comment */
      o[i] = 32; o[i + 1] = 32; i += 2;
      while(i < N && !(s[i] == 42 && s[i + 1] == 47), if(s[i] != 10, o[i] = 32); i++);
      if(i >= N, return(["unterminated /* comment", "unsafe"])); o[i] = 32; o[i + 1] = 32; i += 2; next);
    if(c == 123, depth++; o[i] = 32; i++; next);
    if(c == 125, depth--; if(depth < 0, return(["unbalanced } ", "unsafe"])); o[i] = 32; i++; next);
    if(c == 10 || c == 13, o[i] = if(depth == 0 && c == 10, 59, 32); i++; next);
    if((c >= 65 && c <= 90) || (c >= 97 && c <= 122) || c == 95, \\ identifier
      j = i; while(j <= N && isal(s[j]), j++);
      id = Strchr(s[i .. j - 1]);
      if(!setsearch(allow, id) && iferr(eval(Str("'", id)); 0, E, 1),
        return([Str("calls the GP built-in '", id, "' (a certificate may only assign data)"), "unsafe"]));
      i = j; next);
    if(c >= 48 && c <= 57, while(i <= N && isal(s[i]), i++); next); \\ number: 1e5, 10^-25 ...
    i++);
  if(depth != 0, return(["unbalanced {", "unsafe"]));
  ["", Strchr(o)];
}

ck_scan_result = iferr(ck_scan(ck_file), E, [Str("the scan stopped on a GP error: ", E), "unsafe"]);
if(ck_scan_result[1] != "", \
  print(if(ck_scan_result[2] == "", "FAIL read: ", "FAIL safety: "), ck_scan_result[1]); \
  print("certificate ", ck_file, ": REJECTED (unsafe or unreadable file, not executed)"); quit(1));
ck_read_error = iferr(eval(ck_scan_result[2]); "", E, Str(E));
if(ck_read_error != "", \
  print("FAIL read: cannot read certificate ", ck_file, ": ", ck_read_error); \
  print("certificate ", ck_file, ": REJECTED (unreadable certificate)"); quit(1));
kill(ck_scan_result);

\\ ---------------------------------------------------------------------------------------------
\\ Everything below runs after the certificate was read.

ck_digits = 300;                    \\ working precision (decimal digits)
ck_eps = 10^(-ck_digits / 2);       \\ strict inequalities need a margin larger than this
ck_names = ["cert_format", "label", "n", "P", "d_low", "d_high", "K", "t_low", "t_high", \
  "d_in_K", "sqrt3_in_K", "points", "rattlers", "bonds", "given", "given_tolerance", "claims"];
ck_nfail = 0;
ck_label = ck_file;
ck_claim_slo = 0;                   \\ "strict-local-optimum" is claimed

ck_report(ok, name, detail) =
{
  print(if(ok, "PASS ", "FAIL "), name, ": ", detail);
  if(!ok, ck_nfail++);
  ok;
}
ck_skip(name, why) = print("SKIP ", name, ": ", why);
ck_note(s) = print("NOTE ", s);
\\ run a check body (a closure returning [ok, detail]); a GP error inside it is a failure
ck_run(name, body) =
{
  my(r = iferr(body(), E, [0, Str("error: ", E)]));
  ck_report(r[1], name, r[2]);
}
ck_fmt(r) = if(abs(r) < 10^(-ck_digits), Str("0 (|.| < 1e-", ck_digits, ")"), Strchr([c | c <- Vecsmall(Strprintf("%.3e", r)), c != 32]));
ck_short(v) = my(s = Str(v)); if(#s <= 120, s, Str(strjoin([Strchr(Vecsmall(s)[1 .. 100])]), "... (", #s, " characters)"));
ck_israt(v) = my(ty = type(v)); ty == "t_INT" || ty == "t_FRAC";
\\ an element of K as written in the certificate: a rational or a polynomial in t with
\\ rational coefficients
ck_isKelt(v) = ck_israt(v) || (type(v) == "t_POL" && variable(v) == 't && #select(c -> !ck_israt(c), Vec(v)) == 0);
ck_is2vec(v) = type(v) == "t_VEC" && #v == 2;
ck_printable(s) = #select(c -> c < 32 || c == 127, Vec(Vecsmall(s))) == 0;

ck_finish() =
{
  if(ck_nfail == 0,
    print("certificate ", ck_label, ": ACCEPTED (existence", if(ck_claim_slo, ", strict-local-optimum", ""), ")"); quit(0),
    print("certificate ", ck_label, ": REJECTED (", ck_nfail, " failures)"); quit(1));
}

\\ --- item 7 and the shapes: variables, format, types, sizes, indices ---------------------------

ck_check_variables() =
{
  my(missing = List(), v);
  \\ an unassigned name evaluates to the polynomial variable of the same name
  foreach(ck_names, s, v = eval(s); if(type(v) == "t_POL" && v == eval(Str("'", s)), listput(missing, s)));
  missing = Vec(missing);
  if(#missing,
    print("FAIL variables: the certificate does not assign ", strjoin(missing, ", "));
    print("certificate ", ck_file, ": REJECTED (missing variables)"); quit(1));
  ck_report(1, "variables", Str("all ", #ck_names, " variables of format 1 assigned"));
}

ck_check_structure() =
{
  my(ok = 1, e);
  if(type(label) == "t_STR" && ck_printable(label) && label != "", ck_label = label);
  if(!ck_report(cert_format === 1, "format", Str("cert_format = ", cert_format, " (this checker reads format 1)")),
    ck_finish());
  e = List();
  if(!(type(label) == "t_STR" && label != "" && ck_printable(label)), listput(e, "label is not a non-empty printable string"));
  if(type(n) != "t_INT", listput(e, "n is not an integer"));
  if(!(type(P) == "t_POL" && variable(P) == 'x && poldegree(P) >= 1), listput(e, "P is not a non-constant polynomial in x"));
  if(!(type(K) == "t_POL" && variable(K) == 't && poldegree(K) >= 1 && #select(c -> !ck_israt(c), Vec(K)) == 0),
    listput(e, "K is not a non-constant polynomial in t with rational coefficients"));
  foreach(["d_low", "d_high", "t_low", "t_high", "given_tolerance"], s,
    if(!ck_israt(eval(s)), listput(e, Str(s, " is not a rational number"))));
  if(ck_israt(given_tolerance) && given_tolerance <= 0, listput(e, "given_tolerance is not positive"));
  if(!ck_isKelt(d_in_K), listput(e, "d_in_K is not a polynomial in t with rational coefficients"));
  if(!ck_isKelt(sqrt3_in_K), listput(e, "sqrt3_in_K is not a polynomial in t with rational coefficients"));
  if(!(type(points) == "t_VEC" && #select(p -> !ck_is2vec(p), points) == 0), listput(e, "points is not a vector of [x, y] pairs"));
  if(!(type(given) == "t_VEC" && #select(p -> !(ck_is2vec(p) && ck_israt(p[1]) && ck_israt(p[2])), given) == 0),
    listput(e, "given is not a vector of rational [x, y] pairs"));
  if(!(type(rattlers) == "t_VEC" && #select(r -> type(r) != "t_INT", rattlers) == 0), listput(e, "rattlers is not a vector of integers"));
  if(!(type(bonds) == "t_VEC" && #select(b -> !(ck_is2vec(b) && type(b[1]) == "t_INT" && type(b[2]) == "t_INT"), bonds) == 0),
    listput(e, "bonds is not a vector of integer pairs"));
  if(!(type(claims) == "t_VEC" && #select(c -> type(c) != "t_STR", claims) == 0), listput(e, "claims is not a vector of strings"));
  if(!ck_report(#e == 0, "types", if(#e, strjoin(Vec(e), "; "), "every variable has the type of format 1")),
    ck_skip("all further checks", "the certificate's variables do not have the types of format 1"); ck_finish());

  if(!ck_report(n >= 2 && #points == n && #given == n, "sizes",
      Str("n = ", n, ", ", #points, " points, ", #given, " given points", if(n < 2, " (n must be at least 2)", ""))),
    ck_skip("all further checks", "n, points and given disagree"); ck_finish());
  ok = ck_check_rattler_indices();
  ok = ck_check_bond_indices() && ok;
  ok = ck_check_coordinates() && ok;
  if(!ok, ck_skip("all further checks", "sizes, indices or coordinates are invalid"); ck_finish());
}

ck_check_rattler_indices() =
{
  my(bad = [r | r <- rattlers, r < 1 || r > n]);
  ck_report(#bad == 0 && #Set(rattlers) == #rattlers, "rattler-indices",
    if(#bad, Str("out of range 1..", n, ": ", bad),
      if(#Set(rattlers) != #rattlers, "a rattler is listed twice", Str(#rattlers, " rattlers, indices in range"))));
}

ck_check_bond_indices() =
{
  my(bad = List(), S, dup = List(), ok1, ok2);
  foreach(bonds, b,
    my(i = b[1], j = b[2]);
    if(!(i >= 1 && i <= n && ((j > i && j <= n) || j == -1 || j == -2 || j == -3)), listput(bad, b)));
  ok1 = ck_report(#bad == 0, "bond-indices",
    if(#bad, Str(#bad, " malformed bonds (need [i, j] with 1 <= i < j <= n, or [i, -w] with w in 1..3), first ", bad[1]),
      Str(#bonds, " bonds, indices in range")));
  S = vecsort(bonds);
  for(k = 2, #S, if(S[k] == S[k - 1], listput(dup, S[k])));
  ok2 = ck_report(#dup == 0, "bond-duplicates", if(#dup, Str(#dup, " duplicate bonds, first ", dup[1]), "no bond listed twice"));
  ok1 && ok2;
}

\\ item 5 (types): rattler entries rational, the others polynomials in t (or rationals)
ck_check_coordinates() =
{
  my(R = Set(rattlers), badr = List(), badk = List());
  for(i = 1, n,
    my(p = points[i]);
    if(setsearch(R, i),
      if(!(ck_israt(p[1]) && ck_israt(p[2])), listput(badr, i)),
      if(!(ck_isKelt(p[1]) && ck_isKelt(p[2])), listput(badk, i))));
  ck_report(#badr == 0 && #badk == 0, "coordinates",
    if(#badr || #badk,
      Str(if(#badr, Str("rattlers without rational coordinates: ", Vec(badr), " "), ""),
          if(#badk, Str("points not polynomials in t with rational coefficients: ", Vec(badk)), "")),
      Str(n - #rattlers, " points in K, ", #rattlers, " rattlers with rational coordinates")));
}

ck_check_claims() =
{
  my(has = 0);
  foreach(claims, c,
    if(c == "existence", has = 1,
       c == "strict-local-optimum", ck_claim_slo = 1,
       ck_note(Str("claim \"", c, "\": not checked (unknown to this checker)"))));
  if(!ck_claim_slo && ck_stress_assigned(),
    ck_note("stress is assigned but \"strict-local-optimum\" is not claimed: the stress is not checked"));
  ck_report(has, "claims", Str(if(has, "\"existence\" (statement I) claimed and checked below", "the certificate does not claim \"existence\""),
    if(ck_claim_slo, "; \"strict-local-optimum\" (statement II) claimed and checked after it", "")));
}

\\ --- item 1: P ----------------------------------------------------------------------------------

ck_ok_P = 0;
ck_check_P() =
{
  my(a, d);
  a = ck_report(#select(c -> type(c) != "t_INT", Vec(P)) == 0, "P-integral", Str("P = ", ck_short(P)));
  if(a, ck_report(content(P) == 1, "P-primitive", Str("content ", content(P))), ck_skip("P-primitive", "P-integral failed"));
  ck_report(pollead(P) > 0, "P-leading", Str("leading coefficient ", pollead(P)));
  ck_run("P-irreducible", () -> [polisirreducible(P), Str("degree ", poldegree(P), if(polisirreducible(P), ", irreducible over Q", ", REDUCIBLE over Q"))]);
  d = ck_nfail;
  ck_run("P-interval", () -> my(s); if(d_low >= d_high, [0, Str("d_low = ", d_low, " is not < d_high = ", d_high)],
    s = polsturm(P, [d_low, d_high]); [s == 1, Str(s, " real roots of P in [", d_low, ", ", d_high, "] (need exactly 1)")]));
  ck_ok_P = (ck_nfail == d);  \\ the interval isolates one root (the numeric check needs it)
}

\\ --- item 2: K ----------------------------------------------------------------------------------

ck_ok_K = 0;
ck_check_K() =
{
  my(f0 = ck_nfail);
  ck_run("K-irreducible", () -> [polisirreducible(K), Str("K = ", ck_short(K), ", degree ", poldegree(K), if(polisirreducible(K), ", irreducible over Q", ", REDUCIBLE over Q"))]);
  ck_run("K-interval", () -> my(s); if(t_low >= t_high, [0, Str("t_low = ", t_low, " is not < t_high = ", t_high)],
    s = polsturm(K, [t_low, t_high]); [s == 1, Str(s, " real roots of K in [", t_low, ", ", t_high, "] (need exactly 1)")]));
  ck_ok_K = (ck_nfail == f0);
}

\\ --- item 3: exact identities in K ------------------------------------------------------------

ck_ok_ids = 0;
ck_check_identities() =
{
  my(f0 = ck_nfail);
  ck_run("d-identity", () -> my(r = subst(P, 'x, Mod(d_in_K, K))); [r == 0, if(r == 0, "P(d_in_K) = 0 in Q[t]/(K)", Str("P(d_in_K) = ", ck_short(lift(r)), " mod K, not 0"))]);
  ck_run("sqrt3-identity", () -> my(r = Mod(sqrt3_in_K, K)^2 - 3); [r == 0, if(r == 0, "sqrt3_in_K^2 = 3 in Q[t]/(K)", Str("sqrt3_in_K^2 - 3 = ", ck_short(lift(r)), " mod K, not 0"))]);
  ck_ok_ids = (ck_nfail == f0);
}

\\ --- item 4: the real embedding ---------------------------------------------------------------

ck_t0 = 0; ck_d0 = 0; ck_ok_emb = 0;
ck_check_embedding() =
{
  my(f0 = ck_nfail, rt, s0);
  if(!ck_ok_K, ck_skip("embedding", "K or its interval failed"); ck_skip("sqrt3-sign", "K or its interval failed"); return(0));
  default(realprecision, ck_digits);
  rt = polrootsreal(K, [t_low, t_high]);
  ck_t0 = rt[1];
  ck_d0 = subst(d_in_K, 't, ck_t0) * 1.;
  ck_run("embedding", () -> my(rp, ok, why = ""); 
    ok = (ck_d0 >= d_low && ck_d0 <= d_high);
    if(!ok, why = Str(", d0 NOT in [d_low, d_high] = [", d_low, ", ", d_high, "]"));
    if(ok && ck_ok_P, rp = polrootsreal(P, [d_low, d_high]);
      if(#rp != 1 || abs(rp[1] - ck_d0) > ck_eps, ok = 0; why = ", d0 differs from the root of P in the interval"));
    if(ok && ck_d0 <= ck_eps, ok = 0; why = ", d0 is not positive");
    [ok, Str("t0 = ", ck_fmt(ck_t0), ", d0 = d_in_K(t0) = ", ck_fmt(ck_d0), why,
      if(ok, Str(" in [d_low, d_high], equal to the root of P there (", ck_digits, " digits)"), ""))]);
  ck_run("sqrt3-sign", () -> my(s = subst(sqrt3_in_K, 't, ck_t0) * 1.); [s > 0 && abs(s - sqrt(3)) < ck_eps, Str("sqrt3_in_K(t0) = ", ck_fmt(s))]);
  ck_ok_emb = (ck_nfail == f0);
}

\\ --- item 5: bonds ----------------------------------------------------------------------------

ck_bond_ok(b) =
{
  my(p = points[b[1]], x1 = Mod(p[1], K), y1 = Mod(p[2], K), s3 = Mod(sqrt3_in_K, K), q);
  if(b[2] > 0,
    q = points[b[2]]; (x1 - q[1])^2 + (y1 - q[2])^2 - Mod(d_in_K, K)^2 == 0,
  b[2] == -1, y1 == 0,
  b[2] == -2, s3 * x1 - y1 == 0,
  s3 * (1 - x1) - y1 == 0);
}

ck_check_bonds() =
{
  my(R = Set(rattlers), bad, rb, npair);
  bad = [b | b <- bonds, !ck_bond_ok(b)];
  ck_report(#bad == 0, "bond-identities",
    if(#bad, Str(#bad, " of ", #bonds, " bonds do not hold exactly in K, first ", bad[1],
                 if(#bad > 1, Str(", then ", bad[2 .. min(#bad, 5)]), "")),
      Str("all ", #bonds, " bonds hold exactly in Q[t]/(K) (distance d, or on the wall)")));
  npair = #[b | b <- bonds, b[2] > 0];
  ck_report(npair > 0, "d-attained", Str(npair, " disk-disk bonds at distance exactly d", if(npair, "", " (none: d would not be the minimum distance)")));
  rb = [b | b <- bonds, setsearch(R, b[1]) || (b[2] > 0 && setsearch(R, b[2]))];
  ck_report(#rb == 0, "rattler-bonds", if(#rb, Str(#rb, " bonds involve a rattler, first ", rb[1]), "no rattler is in a bond"));
}

\\ --- item 6: numerical inequalities at t0 ---------------------------------------------------------

ck_check_numeric() =
{
  my(X, Y, W, G, dev, devmax = 0, worst = 0, M, pm = oo, pw = 0, wm = oo, ww = 0, s3, v, dd, badp = List(), badw = List(), nb = 0);
  if(!(ck_ok_emb && ck_ok_ids),
    foreach(["given-distance", "separation", "walls"], s, ck_skip(s, "needs the embedding and the identities of K")); return(0));
  default(realprecision, ck_digits);
  s3 = sqrt(3);
  X = vector(n, i, if(ck_israt(points[i][1]), points[i][1], subst(points[i][1], 't, ck_t0)) * 1.);
  Y = vector(n, i, if(ck_israt(points[i][2]), points[i][2], subst(points[i][2], 't, ck_t0)) * 1.);
  \\ given
  for(i = 1, n,
    dev = max(abs(X[i] - given[i][1]), abs(Y[i] - given[i][2]));
    if(ck_israt(points[i][1]) && ck_israt(points[i][2]), dev = max(abs(points[i][1] - given[i][1]), abs(points[i][2] - given[i][2])));
    if(dev > devmax, devmax = dev; worst = i));
  ck_report(devmax <= given_tolerance, "given-distance",
    Str("max |exact - given| = ", ck_fmt(devmax * 1.), if(worst, Str(" at point ", worst), ""), ", tolerance ", ck_fmt(given_tolerance * 1.)));
  \\ pairs that are not bonds: distance > d0 by more than ck_eps
  M = Map();
  W = vector(n, i, Vecsmall([0, 0, 0]));
  foreach(bonds, b, if(b[2] > 0, mapput(M, b[1] * (n + 1) + b[2], 1), W[b[1]][-b[2]] = 1));
  for(i = 1, n - 1, for(j = i + 1, n,
    if(mapisdefined(M, i * (n + 1) + j), next);
    nb++;
    dd = sqrt((X[i] - X[j])^2 + (Y[i] - Y[j])^2) - ck_d0;
    if(dd < pm, pm = dd; pw = [i, j]);
    if(dd <= ck_eps, listput(badp, [i, j]))));
  ck_report(#badp == 0, "separation",
    Str(nb, " non-bonded pairs, smallest distance - d0 = ", if(nb, Str(ck_fmt(pm), " at ", pw), "none"),
        if(#badp, Str("; ", #badp, " pairs NOT farther than d0 + 1e-", ck_digits / 2, ", first ", badp[1]), "")));
  \\ walls: a point not bonded to a wall is strictly inside; distance to the wall's line
  for(i = 1, n, for(w = 1, 3,
    if(W[i][w], next);
    v = if(w == 1, Y[i], w == 2, (s3 * X[i] - Y[i]) / 2, (s3 * (1 - X[i]) - Y[i]) / 2);
    if(v < wm, wm = v; ww = [i, -w]);
    if(v <= ck_eps, listput(badw, [i, -w]))));
  ck_report(#badw == 0, "walls",
    Str("every point inside the triangle; smallest distance to a non-bonded wall = ", if(ww === 0, "none", Str(ck_fmt(wm), " at ", ww)),
        if(#badw, Str("; ", #badw, " point-wall pairs NOT strictly inside, first ", badw[1]), "")));
  ck_note(Str("given-distance, separation and walls are high-precision floating-point checks at ", ck_digits,
    " digits (gp has no interval arithmetic), not interval bounds; a strict inequality needs a margin > 1e-", ck_digits / 2,
    "; smallest margin found ", if(min(pm, wm) == oo, "none (no inequality to check)", ck_fmt(min(pm, wm)))));
}

\\ --- statement (II), "strict-local-optimum": stress and rigidity --------------------------------
\\ H = the held disks (not rattlers), h = #H. G (B x 2h over K) has one row per bond: pair
\\ [i, j]: (x_i - x_j, y_i - y_j) in i's columns, the negative in j's; wall [i, -w]: the inward
\\ normal in i's columns, (0, 1), (sqrt3, -1), (-sqrt3, -1) for w = 1, 2, 3. (Pair rows are
\\ d * u_ij, wall rows n_w or 2 * n_w: positive row scalings change neither "G^T f = 0 for some
\\ f > 0" nor the rank.) A stress f > 0 with G^T f = 0 and G injective make the held disks a
\\ strict local maximum of d (checker/README.md, "Statement (II)").

\\ an unassigned name evaluates to the polynomial variable of the same name
ck_stress_assigned() = !(type(stress) == "t_POL" && stress == 'stress);

ck_held() = my(R = Set(rattlers)); [i | i <- [1 .. n], !setsearch(R, i)];

\\ the bond-opening matrix over K (entries t_POLMOD mod K); col[i] = position of point i in H
ck_opening_matrix(H) =
{
  my(col = vector(n), G, s3 = Mod(sqrt3_in_K, K), z = Mod(0, K), one = Mod(1, K));
  for(k = 1, #H, col[H[k]] = k);
  G = matrix(#bonds, 2 * #H, r, c, z);
  for(b = 1, #bonds,
    my(i = bonds[b][1], j = bonds[b][2], ci = 2 * col[i] - 1, cj, dx, dy);
    if(j > 0,
      cj = 2 * col[j] - 1;
      dx = Mod(points[i][1] - points[j][1], K); dy = Mod(points[i][2] - points[j][2], K);
      G[b, ci] = dx; G[b, ci + 1] = dy; G[b, cj] = -dx; G[b, cj + 1] = -dy,
    j == -1, G[b, ci + 1] = one,
    j == -2, G[b, ci] = s3; G[b, ci + 1] = -one,
    G[b, ci] = -s3; G[b, ci + 1] = -one));
  G;
}

ck_check_stress_format() =
{
  my(bad);
  if(!ck_stress_assigned(),
    return(ck_report(0, "stress-format", "the certificate claims \"strict-local-optimum\" but does not assign stress")));
  if(type(stress) != "t_VEC" || #stress != #bonds,
    return(ck_report(0, "stress-format", Str("stress is not a vector with one entry per bond (",
      if(type(stress) == "t_VEC", Str(#stress, " entries"), type(stress)), ", ", #bonds, " bonds)"))));
  bad = [b | b <- [1 .. #stress], !ck_isKelt(stress[b])];
  ck_report(#bad == 0, "stress-format",
    if(#bad, Str(#bad, " stress entries are not polynomials in t with rational coefficients (or rationals), first for bond ", bonds[bad[1]]),
      Str(#stress, " entries, one per bond, in K")));
}

\\ 1. G^T stress = 0 exactly in K: for every held disk, both coordinates
ck_check_balance(H, G) =
{
  my(f = Col(vector(#stress, b, Mod(stress[b], K))), r = G~ * f, bad = [k | k <- [1 .. #r], r[k] != 0]);
  ck_report(#bad == 0, "stress-balance",
    if(#bad, Str(#bad, " of ", #r, " equations of G^T stress = 0 fail in Q[t]/(K), first at point ", H[(bad[1] + 1) \ 2],
        if(bad[1] % 2, " (x)", " (y)"), ": ", ck_short(lift(r[bad[1]])), " mod K"),
      Str("G^T stress = 0 exactly in Q[t]/(K): ", #r, " equations (x and y of ", #H, " held disks), ", #stress, " bonds")));
}

\\ 2. every stress entry is positive at t0, with a margin relative to the largest |s_b|
ck_check_positive() =
{
  my(v, m, rmin = oo, w = 0, bad = List());
  default(realprecision, ck_digits);
  v = vector(#stress, b, if(ck_israt(stress[b]), stress[b], subst(stress[b], 't, ck_t0)) * 1.);
  m = vecmax(apply(abs, v));
  if(m <= 10^(-ck_digits), return(ck_report(0, "stress-positive", "every stress entry is 0 at t0")));
  for(b = 1, #v, my(q = v[b] / m); if(q < rmin, rmin = q; w = b); if(q <= ck_eps, listput(bad, b)));
  ck_report(#bad == 0, "stress-positive",
    Str(#v, " entries, smallest s_b / max|s| at t0 = ", ck_fmt(rmin), " at bond ", bonds[w],
      if(#bad, Str("; ", #bad, " entries NOT positive by more than 1e-", ck_digits / 2, " relative, first at bond ", bonds[bad[1]]),
        Str(" (> 1e-", ck_digits / 2, "; floating point at ", ck_digits, " digits)"))));
}

\\ 3. G has full column rank 2h over K (exact: matrank of the t_POLMOD matrix, i.e. Gaussian
\\ elimination in the field Q[t]/(K), K irreducible by K-irreducible); h >= 1, every held disk bonded
ck_check_rigidity(H, G) =
{
  my(deg = vector(n), lone, rk);
  foreach(bonds, b, deg[b[1]]++; if(b[2] > 0, deg[b[2]]++));
  lone = [i | i <- H, deg[i] == 0];
  if(#H < 1, return(ck_report(0, "rigidity", "no held disk (h = 0)")));
  if(#lone, return(ck_report(0, "rigidity", Str(#lone, " held disks without any bond (G has a zero column), first ", lone[1]))));
  rk = matrank(G);
  ck_report(rk == 2 * #H, "rigidity",
    Str("rank of G over Q[t]/(K) = ", rk, if(rk == 2 * #H, " = ", " < "), "2h = ", 2 * #H,
      " (", #bonds, " bonds x ", 2 * #H, " coordinates, exact", if(rk == 2 * #H, "; G is injective)", "; G is NOT injective: some motion of the held disks changes no bond at first order, so the stress proves nothing)")));
}

ck_check_optimality() =
{
  my(f0 = ck_nfail, ok, H, G);
  if(!ck_claim_slo, return(0));
  ok = ck_check_stress_format();
  if(f0 > 0,
    foreach(["stress-balance", "stress-positive", "rigidity"], s, ck_skip(s, "statement (I), existence, failed")); return(0));
  if(!ok,
    foreach(["stress-balance", "stress-positive", "rigidity"], s, ck_skip(s, "no valid stress")); return(0));
  H = ck_held();
  G = iferr(ck_opening_matrix(H), E, ck_report(0, "stress-balance", Str("error building G: ", E)); return(0));
  \\ a GP error inside a check is that check's failure
  iferr(ck_check_balance(H, G), E, ck_report(0, "stress-balance", Str("error: ", E)));
  iferr(ck_check_positive(), E, ck_report(0, "stress-positive", Str("error: ", E)));
  iferr(ck_check_rigidity(H, G), E, ck_report(0, "rigidity", Str("error: ", E)));
}

ck_main() =
{
  ck_check_variables();
  ck_check_structure();
  ck_check_claims();
  ck_check_P();
  ck_check_K();
  ck_check_identities();
  ck_check_embedding();
  ck_check_bonds();
  ck_check_numeric();
  ck_check_optimality();
  ck_finish();
}

iferr(ck_main(), E, \
  print("FAIL internal: the checker stopped on a GP error: ", E); \
  print("certificate ", ck_label, ": REJECTED (", ck_nfail + 1, " failures)"); quit(1));
quit(1);
