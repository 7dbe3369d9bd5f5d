\\ check_exact.gp -- independent checker for tripack exact certificates (formats 1, 2 and 3).
\\
\\ Written in PARI/GP only; shares no code with tripack (which writes certificates with
\\ FLINT/Arb). It re-checks statement (I), "existence": the stated points form a packing of n
\\ points in the unit triangle (0,0), (1,0), (1/2, sqrt(3)/2) whose minimum distance is d, every
\\ stated bond holding exactly and every other pair farther apart than d; and, when claimed,
\\ statement (II), "strict-local-optimum": a stress that is strictly positive, balances exactly in
\\ K (G^T stress = 0) with G of full column rank over K. It also checks the certificate's
\\ provenance against the atlas coordinate file it names. See checker/README.md.
\\
\\ Soundness rules of this file:
\\  * The certificate is DATA. It is read with readstr() and parsed by the tokenizer and
\\    recursive-descent parser below (grammar in checker/README.md); nothing of it is eval'ed
\\    except digit-only strings (integer literals). Anything outside the grammar is "FAIL read".
\\  * Format 3 writes the points and the stress as a(x) + s*b(x) (x = d, s = sqrt 3, deg a, b < deg P):
\\    each is mapped into K as a(d_in_K) + sqrt3_in_K * b(d_in_K), a ring map whatever the
\\    certificate's other values, and checked in K like a format-2 element from then on.
\\  * Every element of K is reduced mod K (its remainder on division by K, degree < deg K) before it
\\    is used; an identity "A = 0 in K" is decided by that exact remainder.
\\  * Every sign is decided exactly: A reduced, A == 0 exactly, or else A(t0) != 0 (K is
\\    irreducible) and its sign comes from an exact rational enclosure of A(t0) on a rational
\\    interval containing t0, refined until the enclosure excludes 0. No floating-point number
\\    takes part in any decision (polrootsreal only proposes refined intervals, which are then
\\    verified by exact sign changes of K).
\\
\\ Usage (normally through checker/check_exact.sh):
\\   CERT_FILE=cert.gp [CHECK_ATLAS_DIR=dir] gp -q -f checker/check_exact.gp < /dev/null
\\ Exit status: 0 = ACCEPTED, 1 = REJECTED. Output: one "PASS name: detail" / "FAIL name: detail"
\\ line per check, "NOTE" and "SKIP" lines, and a final "certificate LABEL: ACCEPTED (existence)",
\\ "certificate LABEL: ACCEPTED (existence, strict-local-optimum)" or
\\ "certificate LABEL: REJECTED (k failures)".

default(debugmem, 0);
ck_file = if(type(cert_file) == "t_STR", cert_file, getenv("CERT_FILE"));
ck_atlas_opt = if(type(atlas_dir) == "t_STR", atlas_dir, getenv("CHECK_ATLAS_DIR"));
if(type(ck_atlas_opt) != "t_STR" || ck_atlas_opt == "", ck_atlas_opt = 0);
ck_profile = (getenv("CHECK_PROFILE") == "1");
if(type(ck_file) != "t_STR" || ck_file == "", \
  print("certificate ?: REJECTED (no certificate file given: set CERT_FILE or cert_file)"); quit(1));
default(secure, 1);

ck_nfail = 0;
ck_label = ck_file;
ck_claim_slo = 0;

\\ =============================================================================================
\\ Reading the certificate: tokenizer and recursive-descent parser (the certificate is data)
\\ =============================================================================================
\\ Token kinds: a punctuation character is its own code (= ; [ ] , ( ) + - * / ^ { }); 1001 an
\\ integer literal (value: the t_INT), 1002 an identifier (value: the name), 1003 a string literal
\\ (value: the t_STR), 1004 a newline outside { } (ends a statement in gp: only allowed between
\\ statements), 1005 the end of the file.

ck_maxdepth = 32;                  \\ nesting of [ ] and ( )
\\ Bounds on every expression, so that no file keeps the parser busy for minutes (a product of
\\ 20,000 factors, 1,000 chained 2^-1000000): the factors of one product and the terms of one sum
\\ (the 280 certificates of data/exact have at most 3 and 57), and every value built, at most
\\ 2^24 bits (2 MB; their largest values are about 100 kB) and of degree at most 4096.
ck_maxfactors = 1000;
ck_maxterms = 10000;
ck_maxbits = 2^24;
ck_maxdegree = 4096;
\\ and all of them together, in proportion to the file (a sum of 100,000 powers of 2^24 bits
\\ each is within the bounds above but would take hours): every value built counts its bytes
\\ once, at most 64 per byte of the file plus 128 MB (t62a.gp, 49 MB, builds 670 MB of values).
ck_maxbuilt = 2^27;
ck_built = 0;
ck_names1 = Set(["cert_format", "label", "n", "P", "d_low", "d_high", "K", "t_low", "t_high", \
  "d_in_K", "sqrt3_in_K", "points", "rattlers", "bonds", "given", "given_tolerance", "claims"]);
ck_names_all = setunion(ck_names1, Set(["stress", "coordinates_file"]));

ck_isalpha(c) = (c >= 65 && c <= 90) || (c >= 97 && c <= 122) || c == 95;
ck_isalnum(c) = (c >= 48 && c <= 57) || (c >= 65 && c <= 90) || (c >= 97 && c <= 122) || c == 95;
ck_errmsg(E) = if(errname(E) == "e_USER", my(v = component(E, 1)); if(type(v) == "t_VEC" && #v == 1, Str(v[1]), Str(v)), Str(E));
ck_lexerr(line, msg) = error(Str("line ", line, ": ", msg));

\\ character class (index: code + 1): letters, digits and _
ck_calnum = Vecsmall(vector(256, k, ck_isalnum(k - 1)));

\\ the first position >= j of s (a Vecsmall of N bytes and a 0 sentinel) that is not a digit.
\\ A certificate is almost all digits (t62a.gp: 49 MB, 1 byte in 500 not a digit), so whole
\\ blocks are tested with vecmin/vecmax (one gp call each, however long), the block doubling
\\ while it is all digits and halving once it is not; only the last < 16 bytes one at a time.
ck_digits_end(s, N, j) =
{
  my(B = 16, e, grow = 1);
  while(B >= 16,
    e = min(j + B - 1, N);
    if(e >= j && vecmin(s[j .. e]) >= 48 && vecmax(s[j .. e]) <= 57,
      j = e + 1; if(grow, B *= 2),
      grow = 0; B \= 2));
  while(s[j] >= 48 && s[j] <= 57, j++);
  j;
}

ck_lex(s0) =
{
  my(N = #s0, s = concat(s0, Vecsmall([0])), A = ck_calnum, i = 1, j, c, line = 1, depth = 0, tk = List(), tv = List(), tl = List());
  \\ s ends with a 0 sentinel (class "other"), so the digit and identifier loops need no bound test
  while(i <= N,
    c = s[i];
    if(c == 32 || c == 9 || c == 13, i++; next);
    if(c == 10, if(depth == 0, listput(tk, 1004); listput(tv, 0); listput(tl, line)); line++; i++; next);
    if(c >= 48 && c <= 57,                                        \\ integer literal
      j = ck_digits_end(s, N, i + 1);
      if(j <= N && (ck_isalpha(s[j]) || s[j] == 46),
        ck_lexerr(line, "malformed number (only integer literals: no '.', exponent letter or suffix)"));
      listput(tk, 1001); listput(tv, eval(Strchr(s[i .. j - 1]))); listput(tl, line); i = j; next);
    if(ck_isalpha(c),                                               \\ identifier
      j = i + 1; while(A[s[j] + 1], j++);
      listput(tk, 1002); listput(tv, Strchr(s[i .. j - 1])); listput(tl, line); i = j; next);
    if(c == 34,                                                     \\ string: printable ASCII, no escapes
      j = i + 1;
      while(j <= N && s[j] != 34,
        if(s[j] < 32 || s[j] > 126 || s[j] == 92,
          ck_lexerr(line, "a string may only contain printable ASCII characters other than \\ and \" (no escapes, no newline)"));
        j++);
      if(j > N, ck_lexerr(line, "unterminated string"));
      listput(tk, 1003); listput(tv, Strchr(s[i + 1 .. j - 1])); listput(tl, line); i = j + 1; next);
    if(c == 92,                                                     \\ only the comment \\ ... end of line
      if(i < N && s[i + 1] == 92, while(i <= N && s[i] != 10, i++); next);
      ck_lexerr(line, "backslash outside a string or a \\\\ comment (a gp metacommand, a line continuation or the \\ operator)"));
    if(c == 47 && i < N && s[i + 1] == 42,                          \\ /* comment */
      i += 2;
      while(i < N && !(s[i] == 42 && s[i + 1] == 47), if(s[i] == 10, line++); i++);
      if(i >= N, ck_lexerr(line, "unterminated /* comment"));
      i += 2; next);
    if(c == 123, if(depth, ck_lexerr(line, "nested {")); depth = 1; listput(tk, c); listput(tv, 0); listput(tl, line); i++; next);
    if(c == 125, if(!depth, ck_lexerr(line, "} without {")); depth = 0; listput(tk, c); listput(tv, 0); listput(tl, line); i++; next);
    if(c == 61 || c == 59 || c == 91 || c == 93 || c == 44 || c == 40 || c == 41 || c == 43 || c == 45 || c == 42 || c == 47 || c == 94,
      listput(tk, c); listput(tv, 0); listput(tl, line); i++; next);
    ck_lexerr(line, Str("character ", if(c >= 33 && c <= 126, Str("'", Strchr(c), "' "), ""), "(code ", c, ") is not allowed outside strings and comments")));
  if(depth, ck_lexerr(line, "unterminated {"));
  listput(tk, 1005); listput(tv, 0); listput(tl, line);
  [Vecsmall(Vec(tk)), Vec(tv), Vecsmall(Vec(tl))];
}

ck_tk = 0; ck_tv = 0; ck_tl = 0; ck_ti = 0; ck_depth = 0;

ck_tokname(k, v) =
{
  if(k == 1001, Str("the number ", if(#Str(v) > 20, "(long)", v)),
     k == 1002, Str("'", v, "'"),
     k == 1003, "a string",
     k == 1004, "the end of the line (outside { }, a newline ends a statement)",
     k == 1005, "the end of the file",
     Str("'", Strchr(k), "'"));
}
ck_perr(msg) = error(Str("line ", ck_tl[ck_ti], ": ", msg, " (found ", ck_tokname(ck_tk[ck_ti], ck_tv[ck_ti]), ")"));
ck_expect(k, what) = if(ck_tk[ck_ti] != k, ck_perr(Str("expected ", what))); ck_ti++;
ck_israt(v) = my(ty = type(v)); ty == "t_INT" || ty == "t_FRAC";

\\ atom := NUMBER | x | t | s | ( sum )
ck_atom() =
{
  my(k = ck_tk[ck_ti], v);
  if(k == 1001, ck_ti++; return(ck_tv[ck_ti - 1]));
  if(k == 1002,
    v = ck_tv[ck_ti];
    if(v == "t", ck_ti++; return('t));
    if(v == "x", ck_ti++; return('x));
    if(v == "s", ck_ti++; return('s));
    ck_perr(Str("unknown identifier '", v, "' (a value may only use integers, the variables x, t and s, + - * / ^ and parentheses)")));
  if(k == 40,
    ck_depth++; if(ck_depth > ck_maxdepth, ck_perr("nesting too deep"));
    ck_ti++; v = ck_sum(); ck_expect(41, "')'"); ck_depth--; return(v));
  ck_perr("expected a number, x, t, s or '('");
}

\\ a value built by the parser within the bounds above, or a one-line error
ck_bounded(v) =
{
  if(type(v) == "t_POL" && poldegree(v) > ck_maxdegree,
    ck_perr(Str("a value of degree ", poldegree(v), " (at most ", ck_maxdegree, ")")));
  my(bytes = sizebyte(v));
  if(bytes * 8 > ck_maxbits, ck_perr(Str("a value of ", bytes, " bytes (at most 2^24 bits)")));
  ck_built += bytes;
  if(ck_built > ck_maxbuilt, ck_perr(Str("the values built exceed ", ck_maxbuilt, " bytes in all (64 per byte of the file + 2^27)")));
  v;
}

\\ power := atom [ ^ [+|-] NUMBER ]
ck_pow() =
{
  my(a = ck_atom(), k, e, bits);
  if(ck_tk[ck_ti] != 94, return(a));
  ck_ti++; k = ck_tk[ck_ti];
  if(k == 43 || k == 45, ck_ti++);
  if(ck_tk[ck_ti] != 1001, ck_perr("the exponent of ^ must be an integer literal (optionally signed)"));
  e = ck_tv[ck_ti]; if(k == 45, e = -e);
  if(ck_israt(a),
    if(a == 0 && e < 0, ck_perr("0 to a negative power"));
    bits = if(a == 0, 1, exponent(numerator(a)) + exponent(denominator(a)) + 2);
    if(abs(e) > 10^6 || bits * abs(e) > 2^24, ck_perr("power too large (at most 2^24 bits)")),
    if(e < 0, ck_perr("a negative exponent is only allowed on a rational number"));
    if(e * max(1, poldegree(a)) > 4096, ck_perr("power of a polynomial of degree > 4096")));
  ck_ti++;
  ck_bounded(a^e);
}

\\ product := power ( (*|/) power )* ; the divisor must be a non-zero rational
ck_prod() =
{
  my(a = ck_pow(), k, b, factors = 1);
  while(1,
    k = ck_tk[ck_ti];
    if(k != 42 && k != 47, break);
    factors++; if(factors > ck_maxfactors, ck_perr(Str("a product of more than ", ck_maxfactors, " factors")));
    if(k == 42, ck_ti++; b = ck_pow(); a = ck_bounded(a * b),
       ck_ti++; b = ck_pow(); if(!ck_israt(b) || b == 0, ck_ti--; ck_perr("division by zero or by a non-constant")); a = ck_bounded(a / b)));
  a;
}

\\ sum := [+|-] product ( (+|-) product )*
ck_sum() =
{
  my(k = ck_tk[ck_ti], a, b, terms = 1);
  if(k == 43 || k == 45, ck_ti++);
  a = ck_prod(); if(k == 45, a = -a);
  while(1,
    k = ck_tk[ck_ti];
    if(k != 43 && k != 45, break);
    terms++; if(terms > ck_maxterms, ck_perr(Str("a sum of more than ", ck_maxterms, " terms")));
    ck_ti++; b = ck_prod(); a = ck_bounded(if(k == 43, a + b, a - b)));
  a;
}

\\ value := STRING | [ ] | [ value ( , value )* ] | sum
ck_value() =
{
  my(k = ck_tk[ck_ti], L);
  if(k == 1003, ck_ti++; return(ck_tv[ck_ti - 1]));
  if(k == 91,
    ck_depth++; if(ck_depth > ck_maxdepth, ck_perr("nesting too deep"));
    ck_ti++; L = List();
    if(ck_tk[ck_ti] == 93, ck_ti++; ck_depth--; return([]));
    while(1,
      listput(L, ck_value());
      k = ck_tk[ck_ti];
      if(k == 44, ck_ti++; next);
      if(k == 93, ck_ti++; break);
      ck_perr("expected ',' or ']'"));
    ck_depth--;
    return(Vec(L)));
  ck_sum();
}

\\ file := ( NEWLINE | statement | { statement* } )* ; statement := NAME = value ;
\\ Returns a Map name -> value.
ck_parse(s) =
{
  my(T = ck_lex(s), V = Map(), name, k, braced = 0, val);
  ck_tk = T[1]; ck_tv = T[2]; ck_tl = T[3]; ck_ti = 1; ck_depth = 0;
  while(1,
    k = ck_tk[ck_ti];
    if(k == 1004, ck_ti++; next);
    if(k == 1005, break);
    if(k == 123, ck_ti++; braced = 1; next);
    if(k == 125, ck_ti++; braced = 0; next);
    if(k != 1002, ck_perr("expected a statement 'name = value;'"));
    name = ck_tv[ck_ti];
    if(!setsearch(ck_names_all, name),
      ck_perr(Str("unknown variable '", name, "' (a certificate only assigns the variables of its format; no function calls or definitions)")));
    if(mapisdefined(V, name), ck_perr(Str("'", name, "' is assigned twice")));
    ck_ti++;
    ck_expect(61, "'='");
    val = ck_value();
    ck_expect(59, "';' after the value");
    mapput(V, name, val));
  V;
}

\\ =============================================================================================
\\ Reporting
\\ =============================================================================================

ck_report(ok, name, detail) =
{
  print(if(ok, "PASS ", "FAIL "), name, ": ", detail);
  if(!ok, ck_nfail++);
  ok;
}
ck_skip(name, why) = print("SKIP ", name, ": ", why);
ck_note(s) = print("NOTE ", s);
\\ run a check body (a closure returning [ok, detail]); a GP error inside it is that check's failure
ck_run(name, body) =
{
  my(r = iferr(body(), E, [0, Str("error: ", ck_errmsg(E))]));
  ck_report(r[1], name, r[2]);
}
ck_fmt(r) = if(r == 0, "0", Strchr([c | c <- Vecsmall(Strprintf("%.3e", r)), c != 32]));
ck_short(v) = my(s = Str(v)); if(#s <= 120, s, Str(Strchr(Vecsmall(s)[1 .. 100]), "... (", #s, " characters)"));
ck_printable(s) = #select(c -> c < 32 || c > 126, Vec(Vecsmall(s))) == 0;
ck_finish() =
{
  if(ck_nfail == 0,
    print("certificate ", ck_label, ": ACCEPTED (existence", if(ck_claim_slo, ", strict-local-optimum", ""), ")"); quit(0),
    print("certificate ", ck_label, ": REJECTED (", ck_nfail, " failures)"); quit(1));
}

\\ =============================================================================================
\\ Exact signs of elements of K at t0
\\ =============================================================================================
\\ ck_K: the defining polynomial (irreducible, checked); ck_iso = [a, b]: rational, contains t0 and
\\ no other root of K (polsturm); refined by ck_refine. ck_lev: Map p -> [lo, hi], lo and hi
\\ multiples of 2^-p with lo <= t0 <= hi and hi - lo <= 3 * 2^-p (the level-p interval).

ck_K = 0; ck_Kz = 0; ck_iso = 0; ck_lev = Map(); ck_pmax = 2^18; ck_maxlevel = 0;

\\ Arithmetic in K = Q[t]/(K) is done on polynomials with rational coefficients, split as
\\ content * primitive integer polynomial: GP's t_POLMOD arithmetic on rational coefficients
\\ spends a gcd on every coefficient product and divides by K in rationals, about 75 times slower
\\ on a degree-56 field (checker/README.md, "Cost"). ck_Kz = K / content(K) has the same
\\ remainders as K.

\\ [c, Z]: a = c * Z with c rational and Z a primitive integer polynomial (or [a, 1], [0, 0])
ck_cz(a) = if(a == 0, [0, 0], type(a) != "t_POL", [a, 1], my(c = content(a)); [c, a / c]);

\\ the remainder of a in Q[t] on division by K (exact)
ck_rem(a) =
{
  my(c);
  if(type(a) != "t_POL" || poldegree(a) < poldegree(ck_Kz), return(a));
  c = content(a);
  c * ((a / c) % ck_Kz);
}

\\ sum_k L[k][1] * L[k][2] for elements of K (unreduced), as [D, S]: the sum is S / D with S an
\\ integer polynomial and D a positive integer. Products of primitive integer polynomials and
\\ one common denominator keep every coefficient operation on integers.
ck_comb(L) =
{
  my(T = vector(#L, k, my(u = ck_cz(L[k][1]), v = ck_cz(L[k][2])); [u[1] * v[1], u[2] * v[2]]), D = 1);
  foreach(T, u, D = lcm(D, denominator(u[1])));
  [D, sum(k = 1, #T, (T[k][1] * D) * T[k][2])];
}

\\ the canonical representative of sum_k L[k][1] * L[k][2] (see ck_red)
ck_comb_red(L) = my(S = ck_comb(L)); ck_red(ck_rem(S[2]) / S[1]);

\\ the canonical representative of an element of K: a rational, or a polynomial in t of degree
\\ 1 .. deg K - 1
ck_red(e) =
{
  my(r);
  if(type(e) != "t_POL" && type(e) != "t_POLMOD", return(e));
  r = if(type(e) == "t_POLMOD", lift(e), ck_rem(e));
  if(type(r) == "t_POL" && poldegree(r) <= 0, polcoef(r, 0), r);
}
ck_Ksign(q) = sign(subst(ck_K, 't, q));

\\ make the isolating interval at most 2^-p wide: a floating-point proposal (polrootsreal) that is
\\ accepted only if K changes sign exactly at its rational ends, both inside the current interval
\\ (which contains exactly one root of K); otherwise exact bisection. deg K >= 2 here, so K has no
\\ rational root and K(m) != 0 at every rational m.
ck_refine(p) =
{
  my(a = ck_iso[1], b = ck_iso[2], w = 1 / 2^p, rho, m, lo, hi, sa, s, old);
  if(b - a <= w, return(0));
  old = default(realprecision);
  default(realprecision, ceil(p * 0.302) + 40);
  \\ the proposal: floor(t0 * 2^(p+2)) from a floating-point root (any error: no proposal)
  m = iferr(rho = polrootsreal(ck_K, [a, b]); if(#rho == 1, floor(rho[1] * 2^(p + 2)), []), E, []);
  default(realprecision, old);
  if(type(m) == "t_INT",
    lo = (m - 1) / 2^(p + 2); hi = (m + 2) / 2^(p + 2);
    if(lo >= a && hi <= b && ck_Ksign(lo) * ck_Ksign(hi) < 0, ck_iso = [lo, hi]; return(1)));
  sa = ck_Ksign(a);
  while(b - a > w, m = (a + b) / 2; s = ck_Ksign(m); if(s == sa, a = m, b = m));
  ck_iso = [a, b];
  2;
}

\\ the level-p interval around t0
ck_tint(p) =
{
  my(I);
  if(mapisdefined(ck_lev, p, &I), return(I));
  if(p > ck_pmax, error(Str("sign not decided with intervals of width 2^-", ck_pmax, " around t0")));
  ck_refine(p);
  I = [floor(ck_iso[1] * 2^p) / 2^p, ceil(ck_iso[2] * 2^p) / 2^p];
  mapput(ck_lev, p, I);
  ck_maxlevel = max(ck_maxlevel, p);
  I;
}

\\ an exact rational interval [lo, hi] containing A(t0), A reduced, from the level-p interval
\\ [m - r, m + r]: A(t0) = A(m) + A'(xi) (t0 - m), |A'(xi)| <= sum_k |a'_k| M^k, M = max(|lo|, |hi|)
ck_encl(A, p) =
{
  my(I, m, r, M, c, D, R);
  if(type(A) != "t_POL", return([A, A]));
  I = ck_tint(p); m = (I[1] + I[2]) / 2; r = (I[2] - I[1]) / 2; M = max(abs(I[1]), abs(I[2]));
  c = subst(A, 't, m);
  D = deriv(A, 't);
  R = r * if(type(D) == "t_POL", subst(Pol(apply(abs, Vec(D)), 't), 't, M), abs(D));
  [c - R, c + R];
}

\\ the exact sign of A(t0), A reduced: [sign, approximate value (for messages only)]
ck_sign2(A) =
{
  my(p = 64, e);
  if(type(A) != "t_POL", return([sign(A), A]));
  \\ A is not 0 and has degree < deg K: A(t0) != 0, so the loop ends (the enclosure width -> 0)
  while(1,
    e = ck_encl(A, p);
    if(e[1] > 0, return([1, (e[1] + e[2]) / 2]));
    if(e[2] < 0, return([-1, (e[1] + e[2]) / 2]));
    p *= 2);
}
ck_sign(A) = ck_sign2(A)[1];

\\ scaled integer enclosures: [lo, hi] with lo / 2^p <= A(t0) <= hi / 2^p
ck_scaled(A, p) = my(e = ck_encl(A, p)); [floor(e[1] * 2^p), ceil(e[2] * 2^p)];
ck_isq(a) = if(a[1] >= 0, [a[1]^2, a[2]^2], a[2] <= 0, [a[2]^2, a[1]^2], [0, max(a[1]^2, a[2]^2)]);
ck_imul(a, b) = my(v = [a[1] * b[1], a[1] * b[2], a[2] * b[1], a[2] * b[2]]); [vecmin(v), vecmax(v)];

\\ =============================================================================================
\\ The certificate's variables (set from the parsed Map; pure data) and their reduced forms
\\ =============================================================================================

ck_V = 0;
ck_get(name) = my(v); if(mapisdefined(ck_V, name, &v), v, 0);
c_format = 0; c_label = 0; c_n = 0; c_P = 0; c_dlow = 0; c_dhigh = 0; c_K = 0; c_tlow = 0; c_thigh = 0;
c_d = 0; c_s3 = 0; c_points = 0; c_rattlers = 0; c_bonds = 0; c_given = 0; c_tol = 0; c_claims = 0;
c_stress = 0; c_cfile = 0;
\\ reduced: coordinates, d, d^2, sqrt3
r_X = 0; r_Y = 0; r_d = 0; r_d2 = 0; r_s3 = 0;

ck_isKelt(v) = ck_israt(v) || (type(v) == "t_POL" && variable(v) == 't && #select(c -> !ck_israt(c), Vec(v)) == 0);
ck_is2vec(v) = type(v) == "t_VEC" && #v == 2;
\\ format 3: a(x) + s*b(x), a and b rationals or polynomials in x with rational coefficients of
\\ degree < deg P (P checked to be a polynomial in x first); [a, b], or 0 when v is not of that form
ck_isxpoly(u, m) = ck_israt(u) || (type(u) == "t_POL" && variable(u) == 'x && poldegree(u) < m && #select(c -> !ck_israt(c), Vec(u)) == 0);
ck_tparts(v) =
{
  my(a, b, m = poldegree(c_P));
  if(ck_israt(v), return([v, 0]));
  if(type(v) != "t_POL" || #setminus(Set(variables(v)), Set(['x, 's])) || poldegree(v, 's) > 1, return(0));
  a = polcoef(v, 0, 's); b = polcoef(v, 1, 's);
  if(ck_isxpoly(a, m) && ck_isxpoly(b, m), [a, b], 0);
}
ck_isTelt(v) = !(ck_tparts(v) === 0);
\\ an element of the certificate's format (2 and 1: of K; 3: of the tower)
ck_iselt(v) = if(c_format == 3, ck_isTelt(v), ck_isKelt(v));
ck_labelok(s) = my(v = Vecsmall(s)); #v >= 1 && #v <= 100 && ck_isalnum(v[1]) && v[1] != 95 && \
  #select(c -> !(ck_isalnum(c) || c == 45 || c == 46), Vec(v)) == 0;

\\ =============================================================================================
\\ Checks
\\ =============================================================================================

ck_read() =
{
  my(L, s, r, t0 = getabstime());
  L = iferr(readstr(ck_file), E, print("FAIL read: cannot read ", ck_file, ": ", ck_errmsg(E));
    print("certificate ", ck_file, ": REJECTED (unreadable file)"); quit(1));
  s = Vecsmall(strjoin(L, "\n"));
  ck_maxbuilt = 64 * #s + 2^27;
  r = iferr(ck_parse(s), E, print("FAIL read: ", ck_file, ": ", ck_errmsg(E), "; the certificate is data, read by the grammar of checker/README.md, never executed");
    print("certificate ", ck_file, ": REJECTED (not a certificate in the data format)"); quit(1));
  ck_V = r;
  ck_report(1, "read", Str(ck_file, ": ", #s, " bytes parsed as data (", #ck_tk, " tokens, ", getabstime() - t0, " ms, ",
    ck_built, " bytes of values built)"));
}

ck_check_variables() =
{
  my(missing, f = ck_get("cert_format"), req = ck_names1);
  if(f === 2 || f === 3, req = setunion(req, ["coordinates_file"]));
  missing = [s | s <- req, !mapisdefined(ck_V, s)];
  if(#missing,
    print("FAIL variables: the certificate does not assign ", strjoin(missing, ", "));
    print("certificate ", ck_file, ": REJECTED (missing variables)"); quit(1));
  ck_report(1, "variables", Str("all ", #req, " variables of format ", f, " assigned"));
}

ck_check_structure() =
{
  my(ok = 1, e);
  c_format = ck_get("cert_format"); c_label = ck_get("label"); c_n = ck_get("n"); c_P = ck_get("P");
  c_dlow = ck_get("d_low"); c_dhigh = ck_get("d_high"); c_K = ck_get("K"); c_tlow = ck_get("t_low");
  c_thigh = ck_get("t_high"); c_d = ck_get("d_in_K"); c_s3 = ck_get("sqrt3_in_K"); c_points = ck_get("points");
  c_rattlers = ck_get("rattlers"); c_bonds = ck_get("bonds"); c_given = ck_get("given");
  c_tol = ck_get("given_tolerance"); c_claims = ck_get("claims"); c_stress = ck_get("stress");
  c_cfile = ck_get("coordinates_file");
  if(type(c_label) == "t_STR" && ck_labelok(c_label), ck_label = c_label);
  if(!ck_report(c_format === 1 || c_format === 2 || c_format === 3, "format",
      Str("cert_format = ", c_format, " (this checker reads formats 1, 2 and 3)")), ck_finish());
  if(c_format == 1 && mapisdefined(ck_V, "coordinates_file"),
    ck_report(0, "format", "coordinates_file is a format-2 variable; format 1 takes the coordinates file from the atlas directory");
    ck_finish());
  e = List();
  if(!(type(c_label) == "t_STR" && ck_labelok(c_label)),
    listput(e, "label is not a string of 1..100 characters A-Z a-z 0-9 . - _ starting with a letter or digit"));
  if(type(c_n) != "t_INT", listput(e, "n is not an integer"));
  if(!(type(c_P) == "t_POL" && variable(c_P) == 'x && poldegree(c_P) >= 1 && #select(c -> !ck_israt(c), Vec(c_P)) == 0),
    listput(e, "P is not a non-constant polynomial in x with rational coefficients"));
  if(!(type(c_K) == "t_POL" && variable(c_K) == 't && poldegree(c_K) >= 1 && #select(c -> !ck_israt(c), Vec(c_K)) == 0),
    listput(e, "K is not a non-constant polynomial in t with rational coefficients"));
  foreach(["d_low", "d_high", "t_low", "t_high", "given_tolerance"], s,
    if(!ck_israt(ck_get(s)), listput(e, Str(s, " is not a rational number"))));
  if(ck_israt(c_tol) && c_tol <= 0, listput(e, "given_tolerance is not positive"));
  if(!ck_isKelt(c_d), listput(e, "d_in_K is not a polynomial in t with rational coefficients"));
  if(!ck_isKelt(c_s3), listput(e, "sqrt3_in_K is not a polynomial in t with rational coefficients"));
  if(!(type(c_points) == "t_VEC" && #select(p -> !ck_is2vec(p), c_points) == 0), listput(e, "points is not a vector of [x, y] pairs"));
  if(!(type(c_given) == "t_VEC" && #select(p -> !(ck_is2vec(p) && ck_israt(p[1]) && ck_israt(p[2])), c_given) == 0),
    listput(e, "given is not a vector of rational [x, y] pairs"));
  if(!(type(c_rattlers) == "t_VEC" && #select(r -> type(r) != "t_INT", c_rattlers) == 0), listput(e, "rattlers is not a vector of integers"));
  if(!(type(c_bonds) == "t_VEC" && #select(b -> !(ck_is2vec(b) && type(b[1]) == "t_INT" && type(b[2]) == "t_INT"), c_bonds) == 0),
    listput(e, "bonds is not a vector of integer pairs"));
  if(!(type(c_claims) == "t_VEC" && #select(c -> type(c) != "t_STR", c_claims) == 0), listput(e, "claims is not a vector of strings"));
  if(c_format >= 2 && !(type(c_cfile) == "t_STR" && c_cfile != "" && Vecsmall(c_cfile)[1] != 47),
    listput(e, "coordinates_file is not a non-empty relative path"));
  if(!ck_report(#e == 0, "types", if(#e, strjoin(Vec(e), "; "), Str("every variable has the type of format ", c_format))),
    ck_skip("all further checks", "the certificate's variables do not have the types of its format"); ck_finish());

  ck_check_provenance_file();

  if(!ck_report(c_n >= 2 && #c_points == c_n && #c_given == c_n, "sizes",
      Str("n = ", c_n, ", ", #c_points, " points, ", #c_given, " given points", if(c_n < 2, " (n must be at least 2)", ""))),
    ck_skip("all further checks", "n, points and given disagree"); ck_finish());
  ok = ck_check_rattler_indices();
  ok = ck_check_bond_indices() && ok;
  ok = ck_check_coordinates() && ok;
  if(!ok, ck_skip("all further checks", "sizes, indices or coordinates are invalid"); ck_finish());
}

ck_check_rattler_indices() =
{
  my(bad = [r | r <- c_rattlers, r < 1 || r > c_n]);
  ck_report(#bad == 0 && #Set(c_rattlers) == #c_rattlers, "rattler-indices",
    if(#bad, Str("out of range 1..", c_n, ": ", bad),
      if(#Set(c_rattlers) != #c_rattlers, "a rattler is listed twice", Str(#c_rattlers, " rattlers, indices in range"))));
}

ck_check_bond_indices() =
{
  my(bad = List(), S, dup = List(), ok1, ok2);
  foreach(c_bonds, b,
    my(i = b[1], j = b[2]);
    if(!(i >= 1 && i <= c_n && ((j > i && j <= c_n) || j == -1 || j == -2 || j == -3)), listput(bad, b)));
  ok1 = ck_report(#bad == 0, "bond-indices",
    if(#bad, Str(#bad, " malformed bonds (need [i, j] with 1 <= i < j <= n, or [i, -w] with w in 1..3), first ", bad[1]),
      Str(#c_bonds, " bonds, indices in range")));
  S = vecsort(c_bonds);
  for(k = 2, #S, if(S[k] == S[k - 1], listput(dup, S[k])));
  ok2 = ck_report(#dup == 0, "bond-duplicates", if(#dup, Str(#dup, " duplicate bonds, first ", dup[1]), "no bond listed twice"));
  ok1 && ok2;
}

ck_check_coordinates() =
{
  my(R = Set(c_rattlers), badr = List(), badk = List());
  for(i = 1, c_n,
    my(p = c_points[i]);
    if(setsearch(R, i),
      if(!(ck_israt(p[1]) && ck_israt(p[2])), listput(badr, i)),
      if(!(ck_iselt(p[1]) && ck_iselt(p[2])), listput(badk, i))));
  ck_report(#badr == 0 && #badk == 0, "coordinates",
    if(#badr || #badk,
      Str(if(#badr, Str("rattlers without rational coordinates: ", Vec(badr), " "), ""),
          if(#badk, Str("points not ", if(c_format == 3, "a(x) + s*b(x) with a, b in Q[x] of degree < deg P", "polynomials in t with rational coefficients"), ": ", Vec(badk)), "")),
      Str(c_n - #c_rattlers, " points in K, ", #c_rattlers, " rattlers with rational coordinates")));
}

ck_check_claims() =
{
  my(has = 0, unknown = [c | c <- c_claims, c != "existence" && c != "strict-local-optimum"]);
  foreach(c_claims, c,
    if(c == "existence", has = 1,
       c == "strict-local-optimum", ck_claim_slo = 1));
  if(!ck_claim_slo && mapisdefined(ck_V, "stress"),
    ck_note("stress is assigned but \"strict-local-optimum\" is not claimed: the stress is not checked"));
  \\ An unknown claim is a rejection: ACCEPTED beside a claim nobody checked would read as its proof.
  if(#unknown,
    return(ck_report(0, "claims", Str("claim \"", if(ck_printable(unknown[1]), ck_short(unknown[1]), "(unprintable)"),
      "\" is unknown to this checker, which checks \"existence\" and \"strict-local-optimum\" only"))));
  ck_report(has, "claims", Str(if(has, "\"existence\" (statement I) claimed and checked below", "the certificate does not claim \"existence\""),
    if(ck_claim_slo, "; \"strict-local-optimum\" (statement II) claimed and checked after it", "")));
}

\\ --- provenance: the atlas coordinate file ---------------------------------------------------
\\ format 2: coordinates_file, relative to the certificate's directory, with basename LABEL.txt;
\\ format 1: DIR/LABEL.txt, DIR = CHECK_ATLAS_DIR (check_exact.sh --atlas) or <cert dir>/../atlas.
\\ Strict mode (an atlas directory given): a format-2 certificate's coordinates_file must hold the
\\ very lines of DIR/LABEL.txt, which is then the file read; a certificate cannot bring its own.
\\ The file: header lines "# n: N", "# label: L", "# d: D" (other "#" lines ignored), then one
\\ line "X Y" per point, decimals with the same number q of digits after the point.

ck_prov_ok = 0; ck_prov_d = 0; ck_prov_qd = 0; ck_prov_path = "";

ck_dirname(f) = my(v = Vecsmall(f), k = 0); for(i = 1, #v, if(v[i] == 47, k = i)); if(k == 0, ".", k == 1, "/", Strchr(v[1 .. k - 1]));
ck_basename(f) = my(v = Vecsmall(f), k = 0); for(i = 1, #v, if(v[i] == 47, k = i)); Strchr(v[k + 1 .. #v]);

\\ a decimal "[-]DIGITS[.DIGITS]" -> [rational, number of decimals]; 0 if malformed
ck_decimal(s) =
{
  my(v = Vecsmall(s), i = 1, neg = 0, j, ip, fp = 0, q = 0);
  if(#v == 0, return(0));
  if(v[1] == 45, neg = 1; i = 2);
  j = i; while(j <= #v && v[j] >= 48 && v[j] <= 57, j++);
  if(j == i, return(0));
  ip = eval(Strchr(v[i .. j - 1]));
  if(j <= #v,
    if(v[j] != 46, return(0));
    i = j + 1; j = i; while(j <= #v && v[j] >= 48 && v[j] <= 57, j++);
    if(j == i || j <= #v, return(0));
    q = j - i; fp = eval(Strchr(v[i .. j - 1])));
  [(if(neg, -1, 1)) * (ip + fp / 10^q), q];
}

\\ split a line at runs of spaces
ck_fields(s) =
{
  my(v = Vecsmall(s), L = List(), i = 1, j);
  while(i <= #v,
    if(v[i] == 32 || v[i] == 9, i++; next);
    j = i; while(j <= #v && v[j] != 32 && v[j] != 9, j++);
    listput(L, Strchr(v[i .. j - 1])); i = j);
  Vec(L);
}

\\ parse an atlas coordinate file: [n, label, [d, q'], [[x, y], ...], q] or an error
ck_read_atlas(path) =
{
  my(L, hn = 0, hl = 0, hd = 0, pts = List(), q = -1, f, a, b, key, val, k, v);
  L = iferr(readstr(path), E, error(Str("cannot read the coordinates file ", path)));
  for(li = 1, #L,
    v = Vecsmall(L[li]);
    \\ a file written on Windows: its lines end in CR LF (readstr drops the LF)
    if(#v && v[#v] == 13, v = v[1 .. #v - 1]; L[li] = Strchr(v));
    if(#v == 0, next);
    if(v[1] == 35,
      \\ "# key: value"
      k = 0; for(i = 1, #v, if(v[i] == 58, k = i; break));
      if(k == 0 || k < 3 || v[2] != 32, next);
      key = Strchr(v[3 .. k - 1]); val = if(k + 2 <= #v && v[k + 1] == 32, Strchr(v[k + 2 .. #v]), "");
      if(key == "n",
        if(!(hn === 0), error(Str(path, ": two '# n:' lines")));
        a = ck_decimal(val); if(a === 0 || a[2] != 0 || a[1] < 0, error(Str(path, ": '# n:' is not an integer")));
        hn = a[1]);
      if(key == "label", if(!(hl === 0), error(Str(path, ": two '# label:' lines"))); hl = val);
      if(key == "d",
        if(!(hd === 0), error(Str(path, ": two '# d:' lines")));
        a = ck_decimal(val); if(a === 0 || a[2] < 1, error(Str(path, ": '# d:' is not a decimal with a decimal point")));
        hd = a);
      next);
    f = ck_fields(L[li]);
    if(#f != 2, error(Str(path, " line ", li, ": not two decimals \"X Y\"")));
    a = ck_decimal(f[1]); b = ck_decimal(f[2]);
    if(a === 0 || b === 0, error(Str(path, " line ", li, ": not two decimals \"X Y\"")));
    if(q < 0, q = a[2]);
    if(a[2] != q || b[2] != q, error(Str(path, " line ", li, ": the coordinates do not all have the same number of decimals")));
    listput(pts, [a[1], b[1]]));
  if(hn === 0 || hl === 0 || hd === 0, error(Str(path, ": a '# n:', '# label:' or '# d:' header line is missing")));
  if(#pts == 0, error(Str(path, ": no coordinates")));
  [hn, hl, hd, Vec(pts), q];
}

ck_check_provenance_file() =
{
  my(path, A, e = List(), bound, badg = List(), qq, atlas, mine, theirs);
  ck_prov_ok = 0;
  path = if(c_format >= 2,
    if(ck_basename(c_cfile) != Str(c_label, ".txt"), listput(e, Str("coordinates_file ", c_cfile, " is not named ", c_label, ".txt")));
    Str(ck_dirname(ck_file), "/", c_cfile),
    Str(if(!(ck_atlas_opt === 0), ck_atlas_opt, Str(ck_dirname(ck_file), "/../atlas")), "/", c_label, ".txt"));
  if(c_format >= 2 && !(ck_atlas_opt === 0) && #e == 0,
    atlas = Str(ck_atlas_opt, "/", c_label, ".txt");
    mine = iferr(readstr(path), E, 0); theirs = iferr(readstr(atlas), E, 0);
    if(theirs === 0, listput(e, Str("strict mode: the atlas has no ", atlas)),
       !(mine === theirs), listput(e, Str("strict mode: coordinates_file ", c_cfile, " is not the atlas's ", atlas))));
  if(c_format >= 2 && !(ck_atlas_opt === 0), path = Str(ck_atlas_opt, "/", c_label, ".txt"));
  ck_prov_path = path;
  if(#e, return(ck_report(0, "provenance", strjoin(Vec(e), "; "))));
  A = iferr(ck_read_atlas(path), E, return(ck_report(0, "provenance", ck_errmsg(E))));
  if(A[2] != c_label, listput(e, Str("the file's label is ", ck_short(A[2]), ", the certificate's ", c_label)));
  if(A[1] != c_n || #A[4] != c_n || #c_points != c_n,
    listput(e, Str("n disagrees: file header ", A[1], ", file points ", #A[4], ", certificate n = ", c_n, ", ", #c_points, " points")));
  if(#A[4] == #c_given,
    for(i = 1, #c_given, if(c_given[i] != A[4][i], listput(badg, i))),
    listput(e, Str(#c_given, " given points, ", #A[4], " points in the file")));
  if(#badg, listput(e, Str(#badg, " given points differ from the file's decimals, first point ", badg[1], ": given ",
    ck_short(c_given[badg[1]]), ", file ", ck_short(A[4][badg[1]]))));
  qq = A[5];
  bound = 10^(5 - qq);
  if(c_tol > bound, listput(e, Str("given_tolerance ", ck_short(c_tol), " exceeds 10^(5 - q) = 1e", 5 - qq, " (the file has q = ", qq, " decimals)")));
  if(#e, return(ck_report(0, "provenance", Str(path, ": ", strjoin(Vec(e), "; ")))));
  ck_prov_d = A[3][1]; ck_prov_qd = A[3][2]; ck_prov_ok = 1;
  ck_report(1, "provenance", Str(path, ": label ", c_label, ", n = ", c_n, "; all ", c_n,
    " given points equal the file's ", qq, "-decimal coordinates exactly; given_tolerance <= 10^(5 - ", qq, ")"));
}

\\ the file's d: |d0 - d_file| <= 10^(1 - q'), decided exactly
ck_check_provenance_d() =
{
  my(tol, s1, s2);
  if(!ck_prov_ok, ck_skip("provenance", "the coordinates file failed (d not compared)"); return(0));
  tol = 10^(1 - ck_prov_qd);
  s1 = ck_sign(ck_red(r_d - ck_prov_d - tol));
  s2 = ck_sign(ck_red(ck_prov_d - r_d - tol));
  ck_report(s1 <= 0 && s2 <= 0, "provenance",
    Str("d0 ", if(s1 <= 0 && s2 <= 0, "is", "is NOT"), " within 10^(1 - ", ck_prov_qd, ") of the file's d = ", ck_short(ck_prov_d * 1.), " (exact)"));
}

\\ --- P and K ------------------------------------------------------------------------------------

ck_ok_P = 0;
ck_check_P() =
{
  my(a, f0 = ck_nfail);
  a = ck_report(#select(c -> type(c) != "t_INT", Vec(c_P)) == 0, "P-integral", Str("P = ", ck_short(c_P)));
  if(a, ck_report(content(c_P) == 1, "P-primitive", Str("content ", content(c_P))), ck_skip("P-primitive", "P-integral failed"));
  ck_report(pollead(c_P) > 0, "P-leading", Str("leading coefficient ", ck_short(pollead(c_P))));
  ck_run("P-irreducible", () -> my(r = polisirreducible(c_P)); [r, Str("degree ", poldegree(c_P), if(r, ", irreducible over Q", ", REDUCIBLE over Q"))]);
  ck_run("P-interval", () -> my(s); if(c_dlow >= c_dhigh, [0, Str("d_low = ", ck_short(c_dlow), " is not < d_high = ", ck_short(c_dhigh))],
    s = polsturm(c_P, [c_dlow, c_dhigh]); [s == 1, Str(s, " real roots of P in [d_low, d_high] (polsturm, closed interval; need exactly 1)")]));
  ck_ok_P = (ck_nfail == f0);
}

\\ format 3: the tower element v = a(x) + s*b(x) (its form checked by "types" or "stress-format")
\\ as an element of K, sum_k a_k d^k + b_k sqrt3 d^k with d = d_in_K and sqrt3 = sqrt3_in_K
\\ reduced, their products d^k and sqrt3 d^k (k < deg P) computed once; formats 1 and 2: v reduced.
ck_dpow = 0; ck_spow = 0;
ck_tower_powers() =
{
  my(m = poldegree(c_P));
  ck_dpow = vector(m); ck_dpow[1] = 1;
  for(k = 2, m, ck_dpow[k] = ck_comb_red([[ck_dpow[k - 1], r_d]]));
  ck_spow = vector(m, k, ck_comb_red([[ck_dpow[k], r_s3]]));
}
ck_elt(v) =
{
  my(ab, L = List());
  if(c_format != 3, return(ck_red(v)));
  if(ck_dpow === 0, ck_tower_powers());
  ab = ck_tparts(v);
  for(part = 1, 2,
    my(u = ab[part], W = if(part == 1, ck_dpow, ck_spow));
    if(ck_israt(u), if(u != 0, listput(L, [u, W[1]])),
      for(k = 0, poldegree(u), my(c = polcoef(u, k)); if(c != 0, listput(L, [c, W[k + 1]])))));
  if(#L == 0, 0, ck_comb_red(Vec(L)));
}

ck_ok_K = 0;
ck_check_K() =
{
  my(f0 = ck_nfail);
  ck_run("K-irreducible", () -> my(r = polisirreducible(c_K)); [r, Str("K = ", ck_short(c_K), ", degree ", poldegree(c_K), if(r, ", irreducible over Q", ", REDUCIBLE over Q"))]);
  ck_run("K-interval", () -> my(s); if(c_tlow >= c_thigh, [0, Str("t_low is not < t_high")],
    s = polsturm(c_K, [c_tlow, c_thigh]);
    if(s == 1 && poldegree(c_K) >= 2 && subst(c_K, 't, c_tlow) * subst(c_K, 't, c_thigh) >= 0, s = -1);
    [s == 1, if(s == -1, "K does not change sign on [t_low, t_high]",
      Str(s, " real roots of K in [t_low, t_high] (polsturm, closed interval; need exactly 1)"))]));
  ck_ok_K = (ck_nfail == f0);
  if(ck_ok_K,
    ck_K = c_K; ck_Kz = c_K / content(c_K);
    ck_iso = if(poldegree(c_K) == 1, my(t0 = -polcoef(c_K, 0) / polcoef(c_K, 1)); [t0, t0], [c_tlow, c_thigh]);
    \\ the reduced (canonical) representatives of everything in K, used from here on
    r_d = ck_red(c_d); r_d2 = ck_comb_red([[c_d, c_d]]); r_s3 = ck_red(c_s3);
    r_X = vector(c_n, i, ck_elt(c_points[i][1])); r_Y = vector(c_n, i, ck_elt(c_points[i][2])));
}

\\ --- exact identities in K -----------------------------------------------------------------------

ck_ok_ids = 0;
\\ p(a) reduced mod K for p in Q[x] and a in K: Horner, reducing after every step
ck_horner(p, a) = my(h = pollead(p)); forstep(k = poldegree(p) - 1, 0, -1, h = ck_comb_red([[h, a], [polcoef(p, k), 1]])); h;
ck_check_identities() =
{
  my(f0 = ck_nfail);
  if(!ck_ok_K, foreach(["d-identity", "sqrt3-identity"], s, ck_skip(s, "K failed")); return(0));
  ck_run("d-identity", () -> my(r = ck_horner(c_P, r_d)); [r == 0, if(r == 0, "P(d_in_K) = 0 in Q[t]/(K)", Str("P(d_in_K) = ", ck_short(r), " mod K, not 0"))]);
  ck_run("sqrt3-identity", () -> my(r = ck_comb_red([[r_s3, r_s3], [-3, 1]])); [r == 0, if(r == 0, "sqrt3_in_K^2 = 3 in Q[t]/(K)", Str("sqrt3_in_K^2 - 3 = ", ck_short(r), " mod K, not 0"))]);
  ck_ok_ids = (ck_nfail == f0);
}

\\ --- the real embedding: exact signs ------------------------------------------------------------

ck_ok_emb = 0;
ck_check_embedding() =
{
  my(f0 = ck_nfail);
  if(!(ck_ok_K && ck_ok_P && ck_ok_ids),
    foreach(["embedding", "sqrt3-sign"], s, ck_skip(s, "P, K or the identities failed")); return(0));
  ck_run("embedding", () -> my(s1, s2, s0, v);
    s1 = ck_sign2(ck_red(r_d - c_dlow)); s2 = ck_sign(ck_red(c_dhigh - r_d)); s0 = ck_sign2(r_d);
    v = s0[2] * 1.;
    [s1[1] >= 0 && s2 >= 0 && s0[1] > 0,
     Str("d0 = d_in_K(t0) ~ ", ck_fmt(v), ": d0 - d_low ", if(s1[1] > 0, "> 0", s1[1] == 0, "= 0", "< 0"),
       ", d_high - d0 ", if(s2 > 0, "> 0", s2 == 0, "= 0", "< 0"), ", d0 ", if(s0[1] > 0, "> 0", "<= 0"),
       " (exact signs)", if(s1[1] >= 0 && s2 >= 0, ": d0 is the root of P in [d_low, d_high]",
         ": d0 is NOT in [d_low, d_high], so the interval isolates another root of P"))]);
  ck_run("sqrt3-sign", () -> my(s = ck_sign(r_s3)); [s > 0, Str("sqrt3_in_K(t0) ", if(s > 0, "> 0: it is +sqrt(3)", "< 0: it is -sqrt(3)"), " (exact sign)")]);
  ck_ok_emb = (ck_nfail == f0);
}

\\ --- bonds -----------------------------------------------------------------------------------------

ck_bond_ok(b) =
{
  my(i = b[1], j = b[2], x = r_X[i], y = r_Y[i]);
  if(j > 0, my(dx = x - r_X[j], dy = y - r_Y[j]); ck_comb_red([[dx, dx], [dy, dy], [-1, r_d2]]) == 0,
     j == -1, y == 0,
     j == -2, ck_comb_red([[r_s3, x], [-1, y]]) == 0,
     ck_comb_red([[r_s3, 1 - x], [-1, y]]) == 0);
}

ck_check_bonds() =
{
  my(R = Set(c_rattlers), bad, rb, npair);
  if(!ck_ok_K, ck_skip("bond-identities", "K failed"),
    bad = [b | b <- c_bonds, !ck_bond_ok(b)];
    ck_report(#bad == 0, "bond-identities",
      if(#bad, Str(#bad, " of ", #c_bonds, " bonds do not hold exactly in K, first ", bad[1],
                   if(#bad > 1, Str(", then ", bad[2 .. min(#bad, 5)]), "")),
        Str("all ", #c_bonds, " bonds hold exactly in Q[t]/(K) (distance d, or on the wall)"))));
  npair = #[b | b <- c_bonds, b[2] > 0];
  ck_report(npair > 0, "d-attained", Str(npair, " disk-disk bonds at distance exactly d", if(npair, "", " (none: d would not be the minimum distance)")));
  rb = [b | b <- c_bonds, setsearch(R, b[1]) || (b[2] > 0 && setsearch(R, b[2]))];
  ck_report(#rb == 0, "rattler-bonds", if(#rb, Str(#rb, " bonds involve a rattler, first ", rb[1]), "no rattler is in a bond"));
}

\\ --- inequalities at t0, decided exactly ---------------------------------------------------------
\\ Each inequality is first tried with interval enclosures of the (reduced) coordinates at 128 and
\\ 512 bits (exact integer interval arithmetic); the few it cannot decide are reduced exactly mod K
\\ (== 0 exactly, or the exact sign by refinement).

ck_levels = [128, 512];

ck_check_given() =
{
  my(p = 256, bad = List(), nex = 0, tol = c_tol, worst = 0, wi = 0);
  for(i = 1, c_n, for(k = 1, 2,
    my(A = if(k == 1, r_X[i], r_Y[i]), g = c_given[i][k], e, s1, s2, dv);
    e = ck_encl(A, p);
    if(e[1] >= g - tol && e[2] <= g + tol,
      dv = max(abs(e[1] - g), abs(e[2] - g)); if(dv > worst, worst = dv; wi = i); next);
    nex++;
    s1 = ck_sign(ck_red(A - g - tol)); s2 = ck_sign(ck_red(g - A - tol));
    if(s1 > 0 || s2 > 0, listput(bad, [i, k]))));
  ck_report(#bad == 0, "given-distance",
    Str(if(#bad, Str(#bad, " coordinates NOT within given_tolerance of the given point, first point ", bad[1][1], if(bad[1][2] == 1, " (x)", " (y)")),
      Str("every coordinate within given_tolerance = ", ck_fmt(tol * 1.), " of its given value (exact; largest |exact - given| <= ", ck_fmt(worst * 1.), if(wi, Str(" at point ", wi), ""), ")")),
      if(nex, Str("; ", nex, " decided by exact reduction"), "")));
}

\\ enclosures of all coordinates at level p, scaled by 2^p (computed on demand)
ck_enc_pts(p, need) =
{
  my(X = vector(c_n), Y = vector(c_n));
  for(i = 1, c_n, if(need[i], X[i] = ck_scaled(r_X[i], p); Y[i] = ck_scaled(r_Y[i], p)));
  [X, Y];
}

ck_check_separation() =
{
  my(M, todo, next_todo, bad = List(), zero = List(), npairs = 0, best = oo, bw = 0, nlev = vector(#ck_levels), nex = 0, E, D2, need, lo, hi, dx, dy, sx, sy, X, Y);
  M = matrix(c_n, c_n);
  foreach(c_bonds, b, if(b[2] > 0, M[b[1], b[2]] = 1));
  todo = List();
  for(i = 1, c_n - 1, for(j = i + 1, c_n, if(!M[i, j], listput(todo, [i, j]))));
  npairs = #todo;
  for(l = 1, #ck_levels,
    my(p = ck_levels[l]);
    if(#todo == 0, break);
    need = vector(c_n); foreach(todo, q, need[q[1]] = 1; need[q[2]] = 1);
    E = ck_enc_pts(p, need); X = E[1]; Y = E[2];
    D2 = ck_encl(r_d2, p); D2 = [floor(D2[1] * 4^p), ceil(D2[2] * 4^p)];
    next_todo = List();
    foreach(todo, q,
      my(i = q[1], j = q[2]);
      dx = [X[i][1] - X[j][2], X[i][2] - X[j][1]]; dy = [Y[i][1] - Y[j][2], Y[i][2] - Y[j][1]];
      sx = ck_isq(dx); sy = ck_isq(dy);
      lo = sx[1] + sy[1] - D2[2]; hi = sx[2] + sy[2] - D2[1];
      if(lo > 0, nlev[l]++; if((lo + hi) / 2 / 4^p < best, best = (lo + hi) / 2 / 4^p; bw = q); next);
      if(hi < 0, listput(bad, q); next);
      listput(next_todo, q));
    todo = next_todo);
  \\ exact: |pi - pj|^2 - d^2 reduced mod K; 0 = an unlisted contact
  foreach(todo, q,
    my(i = q[1], j = q[2], A, s);
    nex++;
    my(dx = r_X[i] - r_X[j], dy = r_Y[i] - r_Y[j]);
    A = ck_comb_red([[dx, dx], [dy, dy], [-1, r_d2]]);
    if(A == 0, listput(zero, q); next);
    s = ck_sign2(A);
    if(s[1] < 0, listput(bad, q), if(s[2] < best, best = s[2]; bw = q)));
  ck_report(#bad == 0 && #zero == 0, "separation",
    Str(npairs, " non-bonded pairs",
      if(#zero, Str("; ", #zero, " pairs at distance EXACTLY d but not listed as bonds (|pi-pj|^2 - d^2 = 0 in K), first ", zero[1]), ""),
      if(#bad, Str("; ", #bad, " pairs CLOSER than d, first ", bad[1]), ""),
      if(#bad == 0 && #zero == 0, Str(", all farther apart than d (exact signs: ", strjoin(vector(#ck_levels, l, Str(nlev[l], " by ", ck_levels[l], "-bit intervals")), ", "),
        ", ", nex, " by exact reduction); smallest |pi-pj|^2 - d^2 ~ ", if(bw === 0, "none", Str(ck_fmt(best * 1.), " at ", bw))), "")));
}

\\ walls: w = 1: y; w = 2: sqrt3 * x - y; w = 3: sqrt3 * (1 - x) - y. A point bonded to a wall is on
\\ it (bond-identities); every other point-wall quantity must be > 0.
ck_wall_exact(i, w) =
{
  my(x = r_X[i], y = r_Y[i]);
  if(w == 1, y, w == 2, ck_comb_red([[r_s3, x], [-1, y]]), ck_comb_red([[r_s3, 1 - x], [-1, y]]));
}

ck_check_walls() =
{
  my(W, todo, next_todo, bad = List(), zero = List(), nq, nlev = vector(#ck_levels), nex = 0, best = oo, bw = 0, S, E, X, Y, need, v, one);
  W = matrix(c_n, 3);
  foreach(c_bonds, b, if(b[2] < 0, W[b[1], -b[2]] = 1));
  todo = List();
  for(i = 1, c_n, for(w = 1, 3, if(!W[i, w], listput(todo, [i, w]))));
  nq = #todo;
  for(l = 1, #ck_levels,
    my(p = ck_levels[l]);
    if(#todo == 0, break);
    need = vector(c_n); foreach(todo, q, need[q[1]] = 1);
    E = ck_enc_pts(p, need); X = E[1]; Y = E[2];
    S = ck_scaled(r_s3, p); one = 2^p;
    next_todo = List();
    foreach(todo, q,
      my(i = q[1], w = q[2]);
      v = if(w == 1, Y[i] * one,
             w == 2, my(a = ck_imul(S, X[i])); [a[1] - Y[i][2] * one, a[2] - Y[i][1] * one],
             my(a = ck_imul(S, [one - X[i][2], one - X[i][1]])); [a[1] - Y[i][2] * one, a[2] - Y[i][1] * one]);
      if(v[1] > 0, nlev[l]++; if((v[1] + v[2]) / 2 / 4^p < best, best = (v[1] + v[2]) / 2 / 4^p; bw = [i, -w]); next);
      if(v[2] < 0, listput(bad, [i, -w]); next);
      listput(next_todo, q));
    todo = next_todo);
  foreach(todo, q,
    my(A = ck_wall_exact(q[1], q[2]), s);
    nex++;
    if(A == 0, listput(zero, [q[1], -q[2]]); next);
    s = ck_sign2(A);
    if(s[1] < 0, listput(bad, [q[1], -q[2]]), if(s[2] < best, best = s[2]; bw = [q[1], -q[2]])));
  ck_report(#bad == 0 && #zero == 0, "walls",
    Str(nq, " point-wall pairs without a wall bond",
      if(#zero, Str("; ", #zero, " points EXACTLY on a wall not listed as a bond, first ", zero[1]), ""),
      if(#bad, Str("; ", #bad, " points OUTSIDE the triangle (beyond the wall), first ", bad[1]), ""),
      if(#bad == 0 && #zero == 0, Str(", all strictly inside (exact signs: ", strjoin(vector(#ck_levels, l, Str(nlev[l], " by ", ck_levels[l], "-bit intervals")), ", "),
        ", ", nex, " by exact reduction); smallest wall quantity ~ ", if(bw === 0, "none", Str(ck_fmt(best * 1.), " at ", bw))), "")));
}

ck_check_inequalities() =
{
  if(!(ck_ok_emb && ck_ok_ids),
    foreach(["given-distance", "separation", "walls"], s, ck_skip(s, "needs the embedding and the identities of K")); return(0));
  ck_step(() -> iferr(ck_check_given(), E, ck_report(0, "given-distance", Str("error: ", ck_errmsg(E)))));
  ck_step(() -> iferr(ck_check_separation(), E, ck_report(0, "separation", Str("error: ", ck_errmsg(E)))));
  ck_step(() -> iferr(ck_check_walls(), E, ck_report(0, "walls", Str("error: ", ck_errmsg(E)))));
}

\\ --- statement (II), "strict-local-optimum": stress and rigidity --------------------------------
\\ H = the held disks (not rattlers), h = #H. G (B x 2h over K) has one row per bond: pair
\\ [i, j]: (x_i - x_j, y_i - y_j) in i's columns, the negative in j's; wall [i, -w]: the inward
\\ normal in i's columns, (0, 1), (sqrt3, -1), (-sqrt3, -1) for w = 1, 2, 3. A stress f > 0 with
\\ G^T f = 0 and G injective make the held disks a strict local maximum of d (checker/README.md).

ck_held() = my(R = Set(c_rattlers)); [i | i <- [1 .. c_n], !setsearch(R, i)];

\\ G over K as a dense matrix of t_POLMODs, for the fallback of ck_check_rigidity only: the checks
\\ below work from G's rows as they come from the points (at t198a, 500 bonds x 390 columns of
\\ field elements of 300 kB each do not fit in gp's 4 GB stack).
ck_opening_matrix(H) = ck_opening_from(H, apply(e -> Mod(e, ck_K), r_X), apply(e -> Mod(e, ck_K), r_Y), Mod(r_s3, ck_K), Mod(1, ck_K));

\\ G's row b: its columns, and its entry in column k (an unreduced difference of reduced elements
\\ of K, built when used): a pair bond [i, j] has (x_i - x_j, y_i - y_j) in i's columns and the
\\ negative in j's; a wall bond the inward normal in i's columns. col: disk -> its index among the
\\ held disks.
ck_opening_cols(b, col) =
{
  my(i = c_bonds[b][1], j = c_bonds[b][2], ci = 2 * col[i] - 1);
  if(j > 0, [ci, ci + 1, 2 * col[j] - 1, 2 * col[j]], j == -1, [ci + 1], [ci, ci + 1]);
}
ck_opening_entry(b, col, k, X = r_X, Y = r_Y, S = r_s3, one = 1) =
{
  my(i = c_bonds[b][1], j = c_bonds[b][2], ci = 2 * col[i] - 1);
  if(j > 0, my(cj = 2 * col[j] - 1);
    if(k == ci, X[i] - X[j], k == ci + 1, Y[i] - Y[j], k == cj, X[j] - X[i], Y[j] - Y[i]),
    j == -1, one,
    k == ci + 1, -one,
    j == -2, S, -S);
}
\\ G with its entries from the points' values X, Y and sqrt 3's S (in K, or their images mod p)
ck_opening_from(H, X, Y, S, one) =
{
  my(col = ck_columns(H), G = matrix(#c_bonds, 2 * #H, r, c, 0 * one));
  for(b = 1, #c_bonds, foreach(ck_opening_cols(b, col), k, G[b, k] = ck_opening_entry(b, col, k, X, Y, S, one)));
  G;
}
ck_columns(H) = my(col = vector(c_n)); for(k = 1, #H, col[H[k]] = k); col;

ck_r_stress = 0;
ck_check_stress_format() =
{
  my(bad);
  if(!mapisdefined(ck_V, "stress"),
    return(ck_report(0, "stress-format", "the certificate claims \"strict-local-optimum\" but does not assign stress")));
  if(type(c_stress) != "t_VEC" || #c_stress != #c_bonds,
    return(ck_report(0, "stress-format", Str("stress is not a vector with one entry per bond (",
      if(type(c_stress) == "t_VEC", Str(#c_stress, " entries"), type(c_stress)), ", ", #c_bonds, " bonds)"))));
  bad = [b | b <- [1 .. #c_stress], !ck_iselt(c_stress[b])];
  ck_report(#bad == 0, "stress-format",
    if(#bad, Str(#bad, " stress entries are not ", if(c_format == 3, "a(x) + s*b(x) with a, b in Q[x] of degree < deg P", "polynomials in t with rational coefficients (or rationals)"), ", first for bond ", c_bonds[bad[1]]),
      Str(#c_stress, " entries, one per bond, in K")));
}

\\ G^T f, one entry per column of G, from G's nonzero entries only (at most 4 per bond, where the
\\ dense product would multiply every zero of G as a t_POLMOD)
ck_check_balance(H) =
{
  my(col = ck_columns(H), T = vector(2 * #H, k, List()), r, bad);
  \\ per column, the bonds that touch it (an index, not the entries: each entry is built when its
  \\ column's equation is summed, then dropped)
  for(b = 1, #c_bonds, foreach(ck_opening_cols(b, col), k, listput(T[k], b)));
  r = vector(2 * #H, k, ck_comb_red(vector(#T[k], m, my(b = T[k][m]); [ck_opening_entry(b, col, k), ck_r_stress[b]])));
  bad = [k | k <- [1 .. #r], r[k] != 0];
  ck_report(#bad == 0, "stress-balance",
    if(#bad, Str(#bad, " of ", #r, " equations of G^T stress = 0 fail in Q[t]/(K), first at point ", H[(bad[1] + 1) \ 2],
        if(bad[1] % 2, " (x)", " (y)"), ": ", ck_short(r[bad[1]]), " mod K"),
      Str("G^T stress = 0 exactly in Q[t]/(K): ", #r, " equations (x and y of ", #H, " held disks), ", #ck_r_stress, " bonds")));
}

\\ every stress entry > 0 at t0: reduced mod K, == 0 exactly or an exact sign
ck_check_positive() =
{
  my(zero = List(), neg = List(), best = oo, bw = 0, s);
  for(b = 1, #ck_r_stress,
    my(A = ck_r_stress[b]);
    if(A == 0, listput(zero, b); next);
    s = ck_sign2(A);
    if(s[1] < 0, listput(neg, b), if(s[2] < best, best = s[2]; bw = b)));
  ck_report(#zero == 0 && #neg == 0, "stress-positive",
    Str(#ck_r_stress, " entries",
      if(#zero, Str("; ", #zero, " entries are 0 in K (exactly), first for bond ", c_bonds[zero[1]]), ""),
      if(#neg, Str("; ", #neg, " entries are NEGATIVE at t0 (exact sign), first for bond ", c_bonds[neg[1]]), ""),
      if(#zero == 0 && #neg == 0, Str(", all > 0 at t0 (exact signs); smallest ~ ", ck_fmt(best * 1.), " at bond ", c_bonds[bw]), "")));
}

\\ A lower bound for rank_K(G), exact, from a prime ideal of degree 1: a prime p (not dividing the
\\ leading coefficient of K's integral multiple Kz nor any denominator of the held points and of
\\ sqrt3_in_K, reduced) and a root r of Kz mod p. Then t -> r is a ring homomorphism from
\\ Z_(p)[t]/(Kz) (which contains those elements, hence every entry of G, their differences, and
\\ lies in Q[t]/(K)) onto F_p, so a minor of G that is nonzero mod (p, t - r) is nonzero in K:
\\ rank_K(G) >= rank_Fp(G mod (p, t - r)). G mod (p, t - r) is built from the images of the points
\\ (2h evaluations, not one per entry). Returns [rank mod p, p, r] or 0 (no usable prime).
ck_rank_mod(H) =
{
  my(Kz = c_K / content(c_K), den = 1, p = 2^61, r, Gp, ev, X, Y, S, col = ck_columns(H));
  foreach(concat([r_s3], concat(vector(#H, k, r_X[H[k]]), vector(#H, k, r_Y[H[k]]))), e,
    den = lcm(den, denominator(content(e))));
  for(k = 1, 60,
    p = nextprime(p + 1);
    if(pollead(Kz) % p == 0 || den % p == 0, next);
    if(!isprime(p), next);                     \\ a proven prime (gp's isprime is a primality proof)
    r = polrootsmod(Kz, p);
    if(#r == 0, next);
    r = r[1];
    if(subst(Kz, 't, r) != 0, next);           \\ r is checked to be a root of Kz mod p
    ev = (e -> if(type(e) == "t_POL", subst(e, 't, r), e * Mod(1, p)));
    X = vector(c_n, i, if(col[i], ev(r_X[i]), 0)); Y = vector(c_n, i, if(col[i], ev(r_Y[i]), 0)); S = ev(r_s3);
    Gp = ck_opening_from(H, X, Y, S, Mod(1, p));
    return([matrank(Gp), p, lift(r)]));
  0;
}

\\ G has full column rank 2h over K: first the modular lower bound (fast), else matrank of the
\\ t_POLMOD matrix (Gaussian elimination in the field Q[t]/(K), K irreducible by K-irreducible).
\\ h >= 1 and every held disk in a bond.
ck_check_rigidity(H) =
{
  my(deg = vector(c_n), lone, rk, m, how);
  foreach(c_bonds, b, deg[b[1]]++; if(b[2] > 0, deg[b[2]]++));
  lone = [i | i <- H, deg[i] == 0];
  if(#H < 1, return(ck_report(0, "rigidity", "no held disk (h = 0)")));
  if(#lone, return(ck_report(0, "rigidity", Str(#lone, " held disks without any bond (G has a zero column), first ", lone[1]))));
  m = ck_rank_mod(H);
  if(!(m === 0) && m[1] == 2 * #H,
    rk = m[1]; how = Str("a 2h x 2h minor of G is nonzero modulo the prime ideal (p, t - r) of K, p = ", m[2], ", r = ", m[3], ", so it is nonzero in K"),
    rk = matrank(ck_opening_matrix(H)); how = Str("matrank over Q[t]/(K)", if(!(m === 0), Str(" (the rank modulo p = ", m[2], " was ", m[1], ", only a lower bound)"), "")));
  ck_report(rk == 2 * #H, "rigidity",
    Str("rank of G over K = ", rk, if(rk == 2 * #H, " = ", " < "), "2h = ", 2 * #H,
      " (", #c_bonds, " bonds x ", 2 * #H, " coordinates, exact: ", how, if(rk == 2 * #H, "; G is injective)", "; G is NOT injective: some motion of the held disks changes no bond at first order, so the stress proves nothing)")));
}

ck_check_optimality() =
{
  my(f0 = ck_nfail, ok, H);
  if(!ck_claim_slo, return(0));
  ok = ck_check_stress_format();
  if(f0 > 0,
    foreach(["stress-balance", "stress-positive", "rigidity"], s, ck_skip(s, "statement (I), existence, failed")); return(0));
  if(!ok,
    foreach(["stress-balance", "stress-positive", "rigidity"], s, ck_skip(s, "no valid stress")); return(0));
  ck_r_stress = vector(#c_stress, b, ck_elt(c_stress[b]));
  H = ck_held();
  ck_step(() -> iferr(ck_check_balance(H), E, ck_report(0, "stress-balance", Str("error: ", ck_errmsg(E)))));
  ck_step(() -> iferr(ck_check_positive(), E, ck_report(0, "stress-positive", Str("error: ", ck_errmsg(E)))));
  ck_step(() -> iferr(ck_check_rigidity(H), E, ck_report(0, "rigidity", Str("error: ", ck_errmsg(E)))));
}

ck_t_start = getabstime();
ck_step(f) = my(t = getabstime()); f(); if(ck_profile, print("NOTE time: ", getabstime() - t, " ms"));

ck_main() =
{
  ck_step(ck_read);
  ck_step(ck_check_variables);
  ck_step(ck_check_structure);
  ck_step(ck_check_claims);
  ck_step(ck_check_P);
  ck_step(ck_check_K);
  ck_step(ck_check_identities);
  ck_step(ck_check_embedding);
  ck_step(() -> if(ck_ok_emb && ck_prov_ok, iferr(ck_check_provenance_d(), E, ck_report(0, "provenance", Str("error: ", ck_errmsg(E)))),
    ck_skip("provenance", "d not compared with the file (needs the coordinates file and the embedding)")));
  ck_step(ck_check_bonds);
  ck_step(ck_check_inequalities);
  ck_step(ck_check_optimality);
  if(ck_profile, print("NOTE time: total ", getabstime() - ck_t_start, " ms; finest interval around t0: 2^-", ck_maxlevel));
  ck_finish();
}

iferr(ck_main(), E, \
  print("FAIL internal: the checker stopped on a GP error: ", ck_errmsg(E)); \
  print("certificate ", ck_label, ": REJECTED (", ck_nfail + 1, " failures)"); quit(1));
quit(1);
