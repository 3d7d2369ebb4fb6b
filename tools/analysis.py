#!/usr/bin/env python3
"""tools/analysis.py - the analysis layer of the experiments (issue 40 item 5).

One module for the numerics that the experiments' run.sh files used to carry as awk programs:
error propagation, means and their standard errors, jackknife, weighted and plain line fits,
interpolation and crossings, block statistics, and the experiment-specific reductions built on
them. A run.sh calls it through tools/analyse (`"$ANALYSE" SUBCOMMAND ARGS...`, exp.sh sets
ANALYSE), which writes TSV rows to stdout. Tests: tests/analysis.py (make test).

Byte-identical tables. The committed results were written by mawk 1.3.4 running
tools/lib/numerics.awk; this module gives the same bytes:
  - every sum runs over the rows in file order, in the same association as the awk it replaces
    (plain loops, no numpy: the order of a floating-point sum changes its last bits);
  - a value read from a table is kept as its text (awk prints a field it did not compute with
    unchanged) and converted to a number only where it is computed with (`num`: strtod's
    leading number, "nan"/"inf" included, as mawk reads them);
  - a computed number printed without a format goes through `astr`, mawk's conversion: an
    integer value in [-(2^31 - 1), 2^31 - 1] as an integer, anything else by %.6g (CONVFMT);
  - printf formats are C's (`cfmt`: Python's % conversions are C's, with a NaN printed as
    C prints it, "-nan" when its sign bit is set);
  - comparisons follow mawk: a field that looks like a decimal number compares as a number, any
    other text ("nan") as a string; a NaN compares equal to every number (mawk's compare()
    returns 0), so NaN == x, NaN <= x and NaN >= x hold and NaN != x does not (`eq`, `le`, ...);
  - squares are x * x (numerics.awk's num_sq), powers a ** b are the C library's pow() as
    mawk's ^ is, log/exp/sqrt the C library's (math.log and friends, with C's NaN and
    infinity where Python would raise).
Methods: first-order error propagation for independent operands unless said otherwise; each
function names its method in its docstring.
"""
import math
import os
import re
import sys

# ---------------------------------------------------------------- awk's numbers and text

_NUM_RE = re.compile(r'[ \t\n]*([+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|inf(?:inity)?|nan))', re.I)
_DEC_RE = re.compile(r'^[ \t\n]*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?[ \t\n]*$')
NAN = float('nan')


def num(x):
    """awk's string-to-number conversion: the longest leading number (strtod), 0 if none.
    mawk reads "nan", "-nan", "inf" as IEEE values."""
    if isinstance(x, float):
        return x
    if isinstance(x, int):
        return float(x)
    m = _NUM_RE.match(x)
    if not m:
        return 0.0
    t = m.group(1).lower()
    if t.lstrip('+-') in ('nan',):
        return -NAN if t.startswith('-') else NAN
    if t.lstrip('+-').startswith('inf'):
        return -math.inf if t.startswith('-') else math.inf
    return float(t)


def looks_numeric(s):
    """mawk's test of whether a field compares as a number: a decimal number with optional sign,
    point and exponent, blanks around; "nan" and "inf" are text."""
    return isinstance(s, (int, float)) or bool(_DEC_RE.match(s))


def astr(x):
    """awk's output of a value without a format (print, concatenation): text unchanged; a number
    with an integer value in [-(2^31 - 1), 2^31 - 1] as an integer (mawk), else %.6g."""
    if isinstance(x, str):
        return x
    x = float(x)
    if not math.isnan(x) and not math.isinf(x) and x == int(x) and -2147483647 <= x <= 2147483647:
        return '%d' % int(x)
    return cfmt('%.6g', x)


def _cmp(a, b):
    """mawk's comparison of two values: numeric if both are numbers or numeric-looking text,
    else as strings; a NaN compares equal (0) to any number."""
    if looks_numeric(a) and looks_numeric(b):
        x, y = num(a), num(b)
        return 1 if x > y else -1 if x < y else 0
    x, y = astr(a), astr(b)
    return 1 if x > y else -1 if x < y else 0


def eq(a, b): return _cmp(a, b) == 0
def ne(a, b): return _cmp(a, b) != 0
def gt(a, b): return _cmp(a, b) > 0
def lt(a, b): return _cmp(a, b) < 0
def ge(a, b): return _cmp(a, b) >= 0
def le(a, b): return _cmp(a, b) <= 0


_SPEC_RE = re.compile(r'%([-+ #0]*)(\*|\d+)?(?:\.(\*|\d*))?([diouxXeEfFgGcs%])')


def cfmt(fmt, *args):
    """C's printf of FMT with ARGS as awk passes them: text converted by `num` for a numeric
    conversion, numbers by `astr` for %s; NaN and infinity as glibc prints them."""
    out, pos, k = [], 0, 0
    args = list(args)
    for m in _SPEC_RE.finditer(fmt):
        out.append(fmt[pos:m.start()])
        pos = m.end()
        flags, width, prec, conv = m.groups()
        if conv == '%':
            out.append('%')
            continue
        if width == '*':
            width = str(int(num(args[k]))); k += 1
        if prec == '*':
            prec = str(int(num(args[k]))); k += 1
        a = args[k] if k < len(args) else ''
        k += 1
        spec = '%' + flags + (width or '') + ('.' + prec if prec is not None else '')
        if conv == 's':
            out.append((spec + 's') % astr(a))
        elif conv == 'c':
            out.append((spec + 's') % (astr(a)[:1] if isinstance(a, str) else chr(int(num(a)))))
        elif conv in 'diouxX':
            v = num(a)
            # mawk's d_to_I: clamped to +-(2^31 - 1), a NaN to -(2^31 - 1)
            v = 2147483647 if v >= 2147483647 else int(v) if v > -2147483647 else -2147483647
            conv2 = 'd' if conv == 'i' else conv
            out.append((spec + conv2) % int(v))
        else:
            v = num(a)
            if math.isnan(v) or math.isinf(v):
                s = ('-' if math.copysign(1.0, v) < 0 else ('+' if '+' in flags else ' ' if ' ' in flags else ''))
                s += 'nan' if math.isnan(v) else 'inf'
                if conv in 'EFG':
                    s = s.upper()
                w = int(width) if width else 0
                out.append(s.ljust(w) if '-' in flags else s.rjust(w))
            else:
                out.append((spec + conv) % v)
    out.append(fmt[pos:])
    return ''.join(out)


def div(a, b):
    """a / b in IEEE arithmetic (mawk divides by zero to an infinity or NaN, Python raises)."""
    try:
        return a / b
    except ZeroDivisionError:
        if math.isnan(a):
            return a
        if a == 0:
            return -NAN              # x86's default NaN: mawk prints 0/0 as -nan
        return math.copysign(math.inf, a) * math.copysign(1.0, b)


def sqrt(x):
    """the C library's sqrt: NaN (printed -nan, as glibc's) for x < 0"""
    if math.isnan(x):
        return x
    return math.sqrt(x) if x >= 0 else -NAN


def log(x):
    """the C library's log: -inf at 0, NaN below"""
    if math.isnan(x):
        return x
    if x == 0:
        return -math.inf
    return math.log(x) if x > 0 else -NAN


def exp(x):
    """the C library's exp (inf on overflow)"""
    try:
        return math.exp(x)
    except OverflowError:
        return math.inf


def pw(a, b):
    """a ^ b as mawk computes it: the C library's pow()"""
    try:
        return math.pow(a, b)
    except (OverflowError, ValueError):
        return -NAN if a < 0 else math.inf


def rows(path):
    """the lines of a TSV file split at tabs (awk -F'\\t': a record per line, the last line
    without its newline kept)"""
    with open(path) as f:
        text = f.read()
    lines = text.split('\n')
    if lines and lines[-1] == '':
        lines.pop()
    return [l.split('\t') for l in lines]


def fld(r, i):
    """awk's $i of a record split into r ($0 is the whole line): "" past the last field"""
    return r[i - 1] if 0 < i <= len(r) else ''


def is_comment(r):
    """awk's /^#/ || $1 == "k"-style header test: a line starting with #"""
    return fld(r, 1).startswith('#')


# ---------------------------------------------------------------- statistics (numerics.awk)

def isnan_text(x):
    """numerics.awk's num_isnan: the value reads as the text nan (a NaN number, or the text
    nan/-nan/+nan in any case): a summary's undefined value"""
    return astr(x).lower() in ('nan', '-nan', '+nan')


class Val:
    """a value and its standard error (numerics.awk's array o: o["v"], o["se"]); each is a
    number or the text "nan"/a field's text"""
    __slots__ = ('v', 'se')

    def __init__(self, v='nan', se='nan'):
        self.v, self.se = v, se

    def pair(self, vf='%.10g', sf='%.4g'):
        """numerics.awk's num_pair: "value<TAB>stderr" (%.10g, %.4g), nan printed as nan"""
        return fmt_nan(vf, self.v) + '\t' + fmt_nan(sf, self.se)

    def row(self, q):
        """numerics.awk's num_row: "Q<TAB>value<TAB>stderr\""""
        return q + '\t' + self.pair()


def fmt_nan(f, x):
    """numerics.awk's num_fmt: X printed with F, "nan" for a NaN or the text nan"""
    return 'nan' if isnan_text(x) else cfmt(f, x)


def parse_pair(s):
    """ "value<TAB>stderr" (as `get` gives it) -> Val of the two texts (awk's split at tab)"""
    p = s.split('\t')
    return Val(p[0], p[1] if len(p) > 1 else '')


def _nan4(*xs):
    return any(isnan_text(x) for x in xs)


def sq(x):
    """x * x (numerics.awk's num_sq, not pow())"""
    x = num(x)
    return x * x


def v_sum(a, sa, b, sb):
    """a + b, errors in quadrature (independent operands; num_sum)"""
    if _nan4(a, sa, b, sb):
        return Val()
    return Val(num(a) + num(b), sqrt(sq(sa) + sq(sb)))


def v_diff(a, sa, b, sb):
    """a - b, errors in quadrature (independent operands; num_diff)"""
    if _nan4(a, sa, b, sb):
        return Val()
    return Val(num(a) - num(b), sqrt(sq(sa) + sq(sb)))


def v_rel2(x, a, sa, b, sb):
    """x, a product or quotient of powers +-1 of a and b, with a's and b's relative errors in
    quadrature (first order; num_rel2)"""
    if _nan4(a, sa, b, sb) or _nan4(x):
        return Val()
    x = num(x)
    return Val(x, abs(x) * sqrt(sq(div(num(sa), num(a))) + sq(div(num(sb), num(b)))))


def v_ratio(a, sa, b, sb):
    """a / b, relative errors in quadrature (num_ratio)"""
    if _nan4(a, sa, b, sb):
        return Val()
    return v_rel2(div(num(a), num(b)), a, sa, b, sb)


def v_product(a, sa, b, sb):
    """a b, relative errors in quadrature (num_product)"""
    if _nan4(a, sa, b, sb):
        return Val()
    return v_rel2(num(a) * num(b), a, sa, b, sb)


def v_rel1(x, a, sa):
    """x, a power +-1 of a times an exact factor, with a's relative error (num_rel1)"""
    if _nan4(x, a, sa):
        return Val()
    x = num(x)
    return Val(x, div(abs(x) * num(sa), abs(num(a))))


def v_inverse(c, a, sa):
    """c / a for an exact c, error |c| sa / a^2 (num_inverse)"""
    if _nan4(c, a, sa):
        return Val()
    c, a = num(c), num(a)
    return Val(div(c, a), div(abs(c) * num(sa), sq(a)))


def v_lin2(w1, a, sa, w2, b, sb):
    """w1 a + w2 b for exact weights, errors in quadrature (num_lin2)"""
    if _nan4(a, sa, b, sb):
        return Val()
    w1, w2 = num(w1), num(w2)
    return Val(w1 * num(a) + w2 * num(b), sqrt(sq(w1 * num(sa)) + sq(w2 * num(sb))))


def v_sqrt(a, sa):
    """sqrt(a), error sa / (2 sqrt(a)) (num_sqrt)"""
    if _nan4(a, sa):
        return Val()
    r = sqrt(num(a))
    return Val(r, div(0.5 * num(sa), r))


def v_div(a, sa, c):
    """(a +- sa) / c for an exact c (num_div)"""
    if _nan4(a, sa, c):
        return Val()
    c = num(c)
    return Val(div(num(a), c), div(num(sa), abs(c)))


def v_scale(a, sa, f):
    """f (a +- sa) for an exact factor f (num_scale)"""
    if _nan4(a, sa, f):
        return Val()
    f = num(f)
    return Val(num(a) * f, num(sa) * abs(f))


def quad(errs):
    """errors added in quadrature, in order (num_quad)"""
    s = 0.0
    for e in errs:
        s += sq(e)
    return sqrt(s)


def mean(xs):
    """arithmetic mean, in order; "nan" for no value or a nan one (num_mean)"""
    n = len(xs)
    if n < 1:
        return 'nan'
    s = 0.0
    for x in xs:
        if isnan_text(x):
            return 'nan'
        s += num(x)
    return s / n


def _mean_spread(xs, error):
    """the mean of XS and ERROR(n, sum of squared deviations from it), the sum in the order of
    the values (the second of two passes); error "nan" for n < 2"""
    n = len(xs)
    m = mean(xs)
    if n < 2 or m == 'nan':
        return Val(m, 'nan')
    ss = 0.0
    for x in xs:
        ss += sq(num(x) - m)
    return Val(m, error(n, ss))


def mean_se(xs):
    """mean and standard error: sample standard deviation (two passes) / sqrt(n), for n
    independent values; error "nan" for n < 2 (num_mean_se)"""
    return _mean_spread(xs, lambda n, ss: sqrt(ss / (n - 1) / n))


def jackknife_se(xs):
    """X the n leave-one-out estimates: their mean and the jackknife error
    sqrt((n - 1) / n sum (x - mean)^2) (Efron & Tibshirani 1993, ch. 11; num_jackknife_se)"""
    return _mean_spread(xs, lambda n, ss: sqrt((n - 1) / n * ss))


def wmean_se(xs, ses):
    """inverse-variance weighted mean, error 1 / sqrt(sum of weights); values with an error
    <= 0 or nan left out (num_wmean_se)"""
    sw = swx = 0.0
    for x, e in zip(xs, ses):
        if usable(x, e):
            w = 1 / sq(e)
            sw += w
            swx += w * num(x)
    if sw == 0:
        return Val()
    return Val(swx / sw, 1 / sqrt(sw))


def usable(v, se):
    """a value with a positive error, neither nan (num_usable)"""
    return not isnan_text(v) and not isnan_text(se) and num(se) > 0


def sum_linear(xs, ses):
    """the sum with the errors added linearly (fully correlated operands; num_sum_linear)"""
    v = e = 0.0
    for x, s in zip(xs, ses):
        v += num(x)
        e += num(s)
    return Val(v, e)


class Line:
    """a fitted line: slope, icpt and their errors, n the rows used"""
    def __init__(self):
        self.slope = self.icpt = self.slope_se = self.icpt_se = 'nan'
        self.n = 0


def line(xs, ys):
    """unweighted least-squares line y = icpt + slope x; errors from the residuals (n - 2
    degrees of freedom), nan for n < 3 (num_line)"""
    o = Line()
    n = len(xs)
    o.n = n
    sx = sy = sxx = sxy = 0.0
    for x, y in zip(xs, ys):
        x, y = num(x), num(y)
        sx += x; sy += y; sxx += x * x; sxy += x * y
    d = n * sxx - sx * sx
    if n < 2 or eq(d, 0):
        return o
    b = (n * sxy - sx * sy) / d
    a = (sy - b * sx) / n
    o.slope, o.icpt = b, a
    if n < 3:
        return o
    r = 0.0
    for x, y in zip(xs, ys):
        r += sq(num(y) - a - b * num(x))
    o.slope_se = sqrt(r / (n - 2) * n / d)
    o.icpt_se = sqrt(r / (n - 2) * sxx / d)
    return o


def wline(xs, ys, ses):
    """weighted (1 / se^2) least-squares line, errors from se as a chi-square fit with known
    errors; rows with se <= 0 or nan left out (num_wline)"""
    o = Line()
    sw = sx = sy = sxx = sxy = 0.0
    m = 0
    for x, y, e in zip(xs, ys, ses):
        if usable(y, e) and not isnan_text(x):
            x, y = num(x), num(y)
            w = 1 / sq(e)
            m += 1
            sw += w; sx += w * x; sy += w * y; sxx += w * x * x; sxy += w * x * y
    o.n = m
    d = sw * sxx - sx * sx
    if m < 2 or eq(d, 0):
        return o
    b = (sw * sxy - sx * sy) / d
    o.slope, o.icpt = b, (sy - b * sx) / sw
    o.slope_se, o.icpt_se = sqrt(sw / d), sqrt(sxx / d)
    return o


def interp(xs, ys, ses, xq, xqse):
    """Y tabulated at increasing X, at xq: linear between the two bracketing points, the error
    from theirs (weights 1 - f, f) and through the local slope from xq's; nan outside
    (num_interp)"""
    n = len(xs)
    for i in range(n - 1):
        if le(xs[i], xq) and le(xq, xs[i + 1]):
            x0, x1, y0, y1 = num(xs[i]), num(xs[i + 1]), num(ys[i]), num(ys[i + 1])
            q = num(xq)
            f = (q - x0) / (x1 - x0)
            b = (y1 - y0) / (x1 - x0)
            return Val((1 - f) * y0 + f * y1,
                       sqrt(sq((1 - f) * num(ses[i])) + sq(f * num(ses[i + 1])) + sq(b * num(xqse))))
    return Val()


def crossing(xs, ys, ses, yq, yqse):
    """the x where the tabulated Y (increasing X) first reaches yq, linear between the
    bracketing points; the errors of yq and of the two points propagated to first order
    (num_crossing)"""
    n = len(xs)
    q = num(yq)
    for i in range(n - 1):
        y0, y1 = num(ys[i]), num(ys[i + 1])
        if le((y0 - q) * (y1 - q), 0) and ne(ys[i], ys[i + 1]):
            x0, x1 = num(xs[i]), num(xs[i + 1])
            f = (q - y0) / (y1 - y0)
            dx, dy = x1 - x0, y1 - y0
            e = [dx / dy * num(yqse), dx * (q - y1) / sq(dy) * num(ses[i]),
                 -dx * (q - y0) / sq(dy) * num(ses[i + 1])]
            return Val(x0 + f * (x1 - x0), quad(e))
    return Val()


# ---------------------------------------------------------------- the TCAF curves (mai-duy-2019)

def tcaf_curve(paths):
    """the eta(k) shells (k n2 vectors eta eta_se) of a tcaf_eta.tsv where eta is defined,
    continued by the shells of a second (high-k) file above the first's largest k"""
    out, kmax = [], 0.0
    for f, p in enumerate(paths, 1):
        for r in rows(p):
            if is_comment(r) or fld(r, 1) == 'k':
                continue
            if f == 1 and fld(r, 4) != 'nan':
                out.append('\t'.join(fld(r, i) for i in range(1, 6)))
                if num(fld(r, 1)) > kmax:
                    kmax = num(fld(r, 1))
            elif f == 2 and fld(r, 4) != 'nan' and num(fld(r, 1)) > kmax * (1 + 1e-9):
                out.append('\t'.join(fld(r, i) for i in range(1, 6)))
    return out


def _shells(path):
    """the (k, eta, se) columns of a curve or tcaf_eta.tsv with eta defined"""
    k, v, s = [], [], []
    for r in rows(path):
        if is_comment(r) or fld(r, 1) == 'k' or fld(r, 4) == 'nan':
            continue
        k.append(fld(r, 1)); v.append(fld(r, 4)); s.append(fld(r, 5))
    return k, v, s


def keff(path, ec, se, tag):
    """Mai-Duy et al. 2019 section 4.2.3: the free system's k where eta_free(k) equals the
    constrained eta(k -> 0) = ec +- se (crossing of the free curve, first from k -> 0), and
    lambda_eff = 2 pi / k_eff; eta_eff = ec (Table 2's eta by construction). Rows
    k_eff_TAG, lambda_eff_TAG, eta_eff_TAG (formerly keff.awk)."""
    k, v, s = _shells(path)
    o = crossing(k, v, s, ec, se)
    out = ['k_eff_%s\t%s\t%s' % (tag, fmt_nan('%.10g', o.v), fmt_nan('%.4g', o.se))]
    if ne(o.v, 'nan'):
        o = v_inverse(2 * 3.14159265358979, o.v, o.se)
    out.append('lambda_eff_%s\t%s\t%s' % (tag, fmt_nan('%.10g', o.v), fmt_nan('%.4g', o.se)))
    out.append(cfmt('eta_eff_%s\t%.10g\t%.4g', tag, ec, se))
    return out


def normalise_curve(path, c0):
    """a curve's eta and se divided by c0 (the free system's eta(k -> 0)): eta(k) / eta(0)"""
    c = num(c0)
    return [cfmt('%s\t%s\t%s\t%.10g\t%.4g', fld(r, 1), fld(r, 2), fld(r, 3), div(num(fld(r, 4)), c),
                 div(num(fld(r, 5)), c)) for r in rows(path)]


def _files_numbered(paths):
    """(file number, row) over files as awk's `FNR == 1 { file++ }` counts them: an empty file
    takes no number"""
    f = 0
    for p in paths:
        rs = rows(p)
        if rs:
            f += 1
        for r in rs:
            yield f, r


def tcaf_grid(a, phi, f_p, f_s, f_t, c_pairs, f0_pairs, free_curve, solvent_curve):
    """Table 2's k_eff and eta_eff at one phi and repulsion under every combination of the open
    choices of Mai-Duy et al. 2019 section 4.2.3 (tab02-readings README, "The grid"; formerly
    grid.awk):
      D  the density of eq. 28 for the constrained system: p particles' (factor f_p), s the
         solvent's n = 4 (f_s = 4 / rho_p), t the total with the bodies (f_t = rho_t / rho_p);
      E  the estimator of the constrained eta(k -> 0): exp, two_mode, integral (c_pairs[E]);
      K  the curve k_eff is read on: free, solvent, ratio (eta_c / eta_f(k -> 0) by E on the
         free curve divided by its own exp eta(k -> 0));
      F  the curve eta_eff is read from: constrained (eta_c), solvent, free (interpolated at k_eff).
    Rows: a phi D E K F k_eff se eta_eff se (crossing and interp of this module)."""
    fk, fv, fs, sk, sv, ss = [], [], [], [], [], []
    for f, r in _files_numbered([free_curve, solvent_curve]):
        if is_comment(r) or fld(r, 1) == 'k':
            continue
        if f == 1:
            fk.append(fld(r, 1)); fv.append(fld(r, 4)); fs.append(fld(r, 5))
        elif f == 2:
            sk.append(fld(r, 1)); sv.append(fld(r, 4)); ss.append(fld(r, 5))
    fac = {'p': f_p, 's': f_s, 't': f_t}
    cv = {e: parse_pair(c_pairs[e]) for e in c_pairs}
    f0 = {e: parse_pair(f0_pairs[e]) for e in f0_pairs}
    e0 = num(f0['exp'].v)
    nv = [div(num(x), e0) for x in fv]
    nsd = [div(num(x), e0) for x in fs]
    out = []
    for D in ('p', 's', 't'):
        for E in ('exp', 'two_mode', 'integral'):
            c = v_scale(cv[E].v, cv[E].se, fac[D])
            for K in ('free', 'solvent', 'ratio'):
                if K == 'free':
                    ke = crossing(fk, fv, fs, c.v, c.se)
                elif K == 'solvent':
                    ke = crossing(sk, sv, ss, c.v, c.se)
                else:
                    r = v_ratio(c.v, c.se, f0[E].v, f0[E].se)
                    ke = crossing(fk, nv, nsd, r.v, r.se)
                for F in ('constrained', 'solvent', 'free'):
                    if F == 'constrained':
                        ee = Val(c.v, c.se)
                    elif isnan_text(ke.v):
                        ee = Val()
                    elif F == 'solvent':
                        ee = interp(sk, sv, ss, ke.v, ke.se)
                    else:
                        ee = interp(fk, fv, fs, ke.v, ke.se)
                    out.append('\t'.join([a, phi, D, E, K, F, ke.pair(), ee.pair()]))
    return out


def summary_dict(path):
    """a summary's rows as awk's { V[$1] = $2; S[$1] = $3 } (the last row of a name wins)"""
    V, S = {}, {}
    for r in rows(path):
        V[fld(r, 1)] = fld(r, 2)
        S[fld(r, 1)] = fld(r, 3)
    return V, S


def pm_text(V, S, q):
    """ "v +- se" of a summary quantity to a number of decimals that falls with its size
    (1 from 100, 2 from 10, 3 from 1, else 4); "-" when absent, "none" when nan"""
    if q not in V:
        return '-'
    if V[q] == 'nan':
        return 'none'
    v, s = V[q], S[q]
    d = _decimals(v)
    return cfmt('%.*f +- %.*f', d, v, d, s)


def _decimals(v):
    if lt(v, 0):
        v = -num(v)
    return 1 if ge(v, 100) else 2 if ge(v, 10) else 3 if ge(v, 1) else 4


def paper_table2(path):
    """Mai-Duy et al.'s Table 2 (paper-table2.tsv: k phi k_eff lambda_eff eta_eff) keyed by
    phi%.4f: (k_eff, eta_eff) texts"""
    pk, pe = {}, {}
    for r in rows(path):
        if not fld(r, 1).startswith('#') and fld(r, 1) != 'k':
            key = cfmt('phi%.4f', fld(r, 2))
            pk[key] = fld(r, 3)
            pe[key] = fld(r, 5)
    return pk, pe


def readings_tables(out, paper2, tier, as_, readings):
    """mai-duy-2019/tab02-readings: its tables from its summary (estimators_aA.tsv,
    table2_reading_R.tsv, eta_r_reading_R.tsv, readings_data.tsv, estimators_data.tsv,
    readings_summary.tsv, paper: eta0_one_minus_phi.tsv). Formatting only, and per reading the
    count of Table 2 values within 10 % (|ours / paper - 1| <= 0.1)."""
    summ = os.path.join(out, 'summary.tsv')
    V, S = summary_dict(summ)
    tags = [fld(r, 1)[4:] for r in rows(summ) if fld(r, 1).startswith('phi_phi')]
    pm = lambda q: pm_text(V, S, q)
    pk, pe = paper_table2(paper2)

    def write(name, lines):
        with open(os.path.join(out, name), 'w') as f:
            f.write(''.join(l + '\n' for l in lines))

    for A in as_:
        L = ['phi\teta_susp (shear, rate 0.1)\tconstrained: exp (eq. 28, C/C0 >= 0.3)\tconstrained: two-mode slow mode (rho particles)\tconstrained: integral\tintegral / eta_susp\tfree: exp\tfree: two-mode\tfree: integral']
        for t in tags:
            g = '_a' + A + '_' + t
            L.append(cfmt('%.4f\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s', V.get('phi_' + t, ''), pm('eta_susp' + g),
                          pm('eta_k0_constrained_exp' + g), pm('eta_k0_constrained_two_mode' + g),
                          pm('eta_k0_constrained_integral' + g), pm('constrained_integral_over_susp' + g),
                          pm('eta_k0_free_exp' + g), pm('eta_k0_free_two_mode' + g), pm('eta_k0_free_integral' + g)))
        write('estimators_a%s.tsv' % A, L)
    for rd in readings:
        L = [cfmt('k\tphi\tk_eff (%s)\tk_eff, paper\teta_eff (%s)\teta_eff, paper', rd, rd)]
        for t in tags:
            g = '_a3.53_' + t
            p = V.get('phi_' + t, '')
            pn = num(p)
            L.append(cfmt('%d\t%.4f\t%s\t%s\t%s\t%s', float(int(pw(13500 * pn / (6 * (1 - pn)), 1 / 3) + 0.5)), p,
                          pm('reading_' + rd + '_k_eff' + g), pk.get(t, ''), pm('reading_' + rd + '_eta_eff' + g),
                          pe.get(t, '')))
        write('table2_reading_%s.tsv' % rd, L)
        L = [cfmt('phi\teta_r TCAF (%s), a = 3.53\teta_r TCAF (%s), a = 6.50\teta_eff (%s), a = 6.50\tk_eff (%s), a = 6.50',
                  rd, rd, rd, rd)]
        for t in tags:
            L.append(cfmt('%.4f\t%s\t%s\t%s\t%s', V.get('phi_' + t, ''), pm('reading_' + rd + '_eta_r_a3.53_' + t),
                          pm('reading_' + rd + '_eta_r_a6.50_' + t), pm('reading_' + rd + '_eta_eff_a6.50_' + t),
                          pm('reading_' + rd + '_k_eff_a6.50_' + t)))
        write('eta_r_reading_%s.tsv' % rd, L)

    def g(q):
        return V[q] + '\t' + S[q] if q in V else 'nan\tnan'
    L = ['# reading\tphi\tk_eff\tse\teta_eff\tse\teta_r_a3.53\tse\teta_r_a6.50\tse (blocks: the readings in order)']
    for r in readings:
        for t in tags:
            L.append(cfmt('%s\t%.6f\t%s\t%s\t%s\t%s', r, V.get('phi_' + t, ''), g('reading_' + r + '_k_eff_a3.53_' + t),
                          g('reading_' + r + '_eta_eff_a3.53_' + t), g('reading_' + r + '_eta_r_a3.53_' + t),
                          g('reading_' + r + '_eta_r_a6.50_' + t)))
        _block_end(L, tags)
    write('readings_data.tsv', L)
    L = ['# a\tphi\teta_susp\tse\texp\tse\ttwo_mode\tse\tintegral\tse\tfree_exp\tse\tfree_integral\tse (blocks: the repulsions in order)']
    for A in as_:
        for t in tags:
            s = '_a' + A + '_' + t
            L.append(cfmt('%s\t%.6f\t%s\t%s\t%s\t%s\t%s\t%s', A, V.get('phi_' + t, ''), g('eta_susp' + s),
                          g('eta_k0_constrained_exp' + s), g('eta_k0_constrained_two_mode' + s),
                          g('eta_k0_constrained_integral' + s), g('eta_k0_free_exp' + s), g('eta_k0_free_integral' + s)))
        _block_end(L, tags)
    write('estimators_data.tsv', L)

    def off(q, p):
        x = div(num(V[q]), num(p)) - 1
        return 1 - div(num(V[q]), num(p)) if lt(x, 0) else x
    defs = {'a': 'J over the particles, rho of the particles, integral',
            'b': 'J and rho with the rigid bodies, integral',
            'c': 'J over the particles, rho of the particles, slow mode of the two-mode fit',
            'd': 'as (a) with rho = 4 (the solvent) for the constrained system',
            'e': 'ratio of (a)s constrained to free eta(k -> 0) on the free curve, the solvent eta(k) there'}
    L = ['reading\tdefinition\teta_eff within 10 % of Table 2\tk_eff within 10 % of Table 2\teta_eff at phi = 0.4940 (paper 15.5091)\teta_r at 0.49, a = 3.53 (paper 9.69)\teta_r at 0.49, a = 6.50 (paper 12.46)']
    for r in readings:
        ne_ = nk = me = mk = 0
        for t in tags:
            q = 'reading_' + r + '_eta_eff_a3.53_' + t
            if q in V:
                me += 1
                if V[q] != 'nan' and le(off(q, pe.get(t, '')), 0.1):
                    ne_ += 1
            q = 'reading_' + r + '_k_eff_a3.53_' + t
            if q in V:
                mk += 1
                if V[q] != 'nan' and le(off(q, pk.get(t, '')), 0.1):
                    nk += 1
        L.append(cfmt('(%s)\t%s\t%d of %d\t%d of %d\t%s\t%s\t%s', r, defs.get(r, ''), ne_, me, nk, mk,
                      pm('reading_' + r + '_eta_eff_a3.53_phi0.4940'), pm('reading_' + r + '_eta_r_a3.53_phi0.4940'),
                      pm('reading_' + r + '_eta_r_a6.50_phi0.4940')))
    write('readings_summary.tsv', L)
    if tier == 'paper':
        L = ['phi\teta_eff, paper Table 2\teta_0 (1 - phi)\tratio']
        for t in tags:
            e0, s0, p = num(V.get('eta0_solvent_a3.53', '')), num(S.get('eta0_solvent_a3.53', '')), num(V.get('phi_' + t, ''))
            L.append(cfmt('%.4f\t%s\t%.3f +- %.3f\t%s', p, pe.get(t, ''), e0 * (1 - p), s0 * (1 - p),
                          pm('table2_eta_eff_over_eta0_one_minus_phi_' + t)))
        write('eta0_one_minus_phi.tsv', L)


def _block_end(lines, tags):
    """two blank lines after a block of rows (gnuplot's index separator; awk's printf "\\n\\n")"""
    if tags:
        lines[-1] += '\n\n'
    else:
        lines.append('\n')


def readings_grid_decision(paper2, summary, grid_rows, grid_out):
    """mai-duy-2019/tab02-readings, "The grid" (README): per combination of the open choices,
    Table 2's rows (a = 3.53) under the decision rule (value +- 2 se inside the paper's value
    +- 10 %: pass; wholly outside: fail; else unresolved; none where the curve is not reached:
    fail), eta_eff at 0.4940 and the TCAF eta_r(0.49) = eta_susp / eta_eff at both repulsions
    (v_ratio). Writes GRID_OUT; returns the summary rows."""
    pk, pe = paper_table2(paper2)
    es, ess = {}, {}
    for r in rows(summary):
        if fld(r, 1).startswith('eta_susp_a'):
            es[fld(r, 1)] = fld(r, 2); ess[fld(r, 1)] = fld(r, 3)

    def decide(v, se, p):
        lo, hi = 0.9 * num(p), 1.1 * num(p)
        if isnan_text(v):
            return 'fail'
        if isnan_text(se):
            # no error, no decision (the awk this replaced passed it: mawk's NaN compares equal)
            return 'unresolved'
        v, se = num(v), num(se)
        if ge(v - 2 * se, lo) and le(v + 2 * se, hi):
            return 'pass'
        if lt(v + 2 * se, lo) or gt(v - 2 * se, hi):
            return 'fail'
        return 'unresolved'
    order, comb, cnt, er, erf, ev, evs = [], {}, {}, {}, {}, {}, {}
    for r in rows(grid_rows):
        if is_comment(r):
            continue
        c = '_'.join(fld(r, i) for i in (3, 4, 5, 6))
        if c not in comb:
            comb[c] = [fld(r, i) for i in (3, 4, 5, 6)]
            order.append(c)
        if fld(r, 1) == '3.53' and fld(r, 2) in pe:
            k = (c, 'e', decide(fld(r, 9), fld(r, 10), pe[fld(r, 2)]))
            cnt[k] = cnt.get(k, 0) + 1
            k = (c, 'k', decide(fld(r, 7), fld(r, 8), pk[fld(r, 2)]))
            cnt[k] = cnt.get(k, 0) + 1
        if fld(r, 2) == 'phi0.4940':
            q = 'eta_susp_a' + fld(r, 1) + '_phi0.4940'
            if q in es and not isnan_text(fld(r, 9)):
                o = v_ratio(es[q], ess[q], fld(r, 9), fld(r, 10))
            else:
                o = Val()
            A = fld(r, 1)
            er[c, A] = o.pair()
            erf[c, A] = fmt_nan('%.2f', o.v) + ' +- ' + fmt_nan('%.2f', o.se)
            ev[c, A] = fld(r, 9); evs[c, A] = fld(r, 10)
    G = ['D\tE\tK\tF\teta_eff rows pass / fail / unresolved (of 11)\tk_eff rows pass / fail / unresolved (of 11)\teta_eff at 0.4940 (paper 15.5091)\teta_r(0.49), a = 3.53 (paper 9.69)\teta_r(0.49), a = 6.50 (paper 12.46)']
    out = []
    for c in order:
        d = comb[c]
        n = lambda w, o: cnt.get((c, w, o), 0)
        G.append(cfmt('%s\t%s\t%s\t%s\t%d / %d / %d\t%d / %d / %d\t%s\t%s\t%s', d[0], d[1], d[2], d[3],
                      n('e', 'pass'), n('e', 'fail'), n('e', 'unresolved'), n('k', 'pass'), n('k', 'fail'),
                      n('k', 'unresolved'),
                      fmt_nan('%.2f', ev.get((c, '3.53'), '')) + ' +- ' + fmt_nan('%.2f', evs.get((c, '3.53'), '')),
                      erf.get((c, '3.53'), '-'), erf.get((c, '6.50'), '-')))
        for A in ('3.53', '6.50'):
            if (c, A) in er:
                x = er[c, A].split('\t')
                out.append('grid_%s_eta_r_a%s_phi0.4940\t%s\t%s' % (c, A, x[0], x[1]))
        out.append(cfmt('grid_%s_table2_eta_eff_rows_pass\t%d\t0', c, n('e', 'pass')))
        out.append(cfmt('grid_%s_table2_k_eff_rows_pass\t%d\t0', c, n('k', 'pass')))
    with open(grid_out, 'w') as f:
        f.write(''.join(l + '\n' for l in G))
    return out


def largest_sigmas(summary, q):
    """the largest |value| / stderr over the summary rows named Q_a* with a positive stderr
    (%.3g), and their count"""
    m, n = 0.0, 0
    for r in rows(summary):
        if fld(r, 1).startswith(q + '_a') and gt(fld(r, 3), 0):
            x = div(num(fld(r, 2)), num(fld(r, 3)))
            x = -x if lt(x, 0) else x
            if gt(x, m):
                m = x
            n += 1
    return [cfmt('largest_sigmas_%s\t%.3g\t0', q, m), cfmt('largest_sigmas_%s_cases\t%d\t0', q, n)]


def log_ratios(col, blocks_table, fit_table):
    """log(e / e_blocks) per shell (keyed by n2, column 2) of a `dpd tcaf-fit --model exp` table's
    column COL (4: the propagated error, 5: the bound) against the block errors of the run's
    tcaf_eta.tsv (column 5), both positive; printed as awk prints a number (%.6g)"""
    b = {}
    for r in rows(blocks_table):
        if not fld(r, 1).startswith('#') and fld(r, 1) != 'k' and fld(r, 5) != 'nan' and gt(fld(r, 5), 0):
            b[fld(r, 2)] = fld(r, 5)
    out = []
    for r in rows(fit_table):
        c = fld(r, col)
        if not fld(r, 1).startswith('#') and fld(r, 1) != 'k' and fld(r, 2) in b and c != 'nan' and gt(c, 0):
            out.append(astr(log(div(num(c), num(b[fld(r, 2)])))))
    return out


def geometric_mean_rows(q, kind, logs):
    """the geometric mean exp(mean log) of ratios from their logs, its error exp(m) se(m)
    (the logs independent: mean_se); with KIND propagated also the count"""
    o = mean_se(logs)
    m = num(o.v)
    out = [cfmt('%s\t%.6g\t%.3g', q, exp(m), exp(m) * num(o.se))]
    if kind == 'propagated':
        out.append(cfmt('exp_se_ratio_shells_a3.53\t%d\t0', len(logs)))
    return out


def eta0_one_minus_phi_rows(summary, paper2, e0pair):
    """Table 2's eta_eff against eta_0 (1 - phi): eta_eff / (eta_0 (1 - phi)), the error eta_0's
    (v_rel1; the paper's eta_eff and phi exact)"""
    phi = {}
    for r in rows(summary):
        if fld(r, 1).startswith('phi_phi'):
            phi[fld(r, 1)[4:]] = fld(r, 2)
    z = parse_pair(e0pair)
    out = []
    for r in rows(paper2):
        if is_comment(r) or fld(r, 1) == 'k':
            continue
        t = cfmt('phi%.4f', fld(r, 2))
        den = num(z.v) * (1 - num(phi.get(t, '')))
        o = v_rel1(div(num(fld(r, 5)), den), z.v, z.se)
        out.append(o.row('table2_eta_eff_over_eta0_one_minus_phi_' + t))
    return out


def eta_at_wavelength(path, lam, name):
    """eta_free(k) at k = 2 pi / lambda, linear between the two shells of a tcaf_eta.tsv that
    bracket k (interp; the shells' errors weighted by the interpolation, k exact); nan outside
    the measured shells (formerly etak.awk)"""
    k, v, s = _shells(path)
    return [interp(k, v, s, 2 * 3.14159265358979 / num(lam), 0.0).row(name)]


def tab02_data_row(summary, t, kp):
    """mai-duy-2019/tab02-effective-viscosity: one row of table2_data.tsv (k phi k_eff lambda_eff
    eta_eff eta_k0_free and the exp and two-mode estimators' k_eff and eta_eff, each value se)"""
    V, S = summary_dict(summary)
    g = lambda q: V[q] + '\t' + S[q] if q in V else 'nan\tnan'
    return ['\t'.join([kp, V.get('phi_' + t, ''), g('k_eff_' + t), g('lambda_eff_' + t), g('eta_eff_' + t),
                       g('eta_k0_free_' + t), g('k_eff_exp_' + t), g('eta_eff_exp_' + t),
                       g('k_eff_two_mode_' + t), g('eta_eff_two_mode_' + t)])]


def tab02_table(paper2, data):
    """mai-duy-2019/tab02-effective-viscosity: Table 2 beside the paper's values (value +- se)"""
    pk, pl, pe = {}, {}, {}
    for r in rows(paper2):
        if not fld(r, 1).startswith('#') and fld(r, 1) != 'k':
            pk[fld(r, 1)] = fld(r, 3); pl[fld(r, 1)] = fld(r, 4); pe[fld(r, 1)] = fld(r, 5)
    pm = lambda v, e: 'none' if v == 'nan' else cfmt('%.3f +- %.3f', v, e)
    out = []
    for i, r in enumerate(rows(data)):
        if i == 0:
            out.append('k\tphi\tk_eff\tk_eff, paper\tlambda_eff\tlambda_eff, paper\teta_eff\teta_eff, paper\tfree eta(k -> 0)\teta_eff, two-mode (second estimator)\teta_eff, eq. 28 amplitude 1 (the literal fit of the paper, its artefact)\tk_eff, eq. 28 amplitude 1')
            continue
        f = lambda j: fld(r, j)
        out.append(cfmt('%s\t%.4f\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s', f(1), f(2), pm(f(3), f(4)), pk.get(f(1), ''),
                        pm(f(5), f(6)), pl.get(f(1), ''), pm(f(7), f(8)), pe.get(f(1), ''), pm(f(9), f(10)),
                        pm(f(17), f(18)), pm(f(13), f(14)), pm(f(11), f(12))))
    return out


def solvent_at_paper_keff(paper2, solvent_eta):
    """mai-duy-2019/tab02-effective-viscosity's side check: the pure solvent's eta(k) at each of
    the paper's lambda_eff (eta_at_wavelength), beside the paper's phi, k_eff and eta_eff"""
    out = []
    for r in rows(paper2):
        if fld(r, 1).startswith('#') or fld(r, 1) == 'k':
            continue
        phi, ke, le_, ee = fld(r, 2), fld(r, 3), fld(r, 4), fld(r, 5)
        x = eta_at_wavelength(solvent_eta, le_, 'x')[0].split('\t')
        out.append('\t'.join([phi, ke, ee, x[1] + '\t' + x[2]]))
    return out


def rename_rows(path, pairs):
    """the rows named OLD of a summary, in file order, under the name NEW (pairs OLD NEW ...)"""
    m = dict(zip(pairs[0::2], pairs[1::2]))
    return [m[fld(r, 1)] + '\t' + fld(r, 2) + '\t' + fld(r, 3) for r in rows(path) if fld(r, 1) in m]


def summary_diff(summary, a, b, q):
    """Q = summary quantity A - B, errors in quadrature (v_diff; the last row of a name)"""
    V, S = summary_dict(summary)
    return [v_diff(V.get(a, ''), S.get(a, ''), V.get(b, ''), S.get(b, '')).row(q)]


def tolerance_to_pass(summary, q, theory, out):
    """the smallest relative tolerance t of a band theory (1 -+ t) that holds Q's value +- 2 se
    (the decision rule's PASS): OUT = (|v - theory| + 2 se) / |theory|, its error se / |theory|
    (the value's; the error of se itself is not carried). For a band whose tolerance was chosen
    with the value known: how far below it the outcome would stay PASS"""
    V, S = summary_dict(summary)
    if q not in V:
        raise SystemExit('analysis.py tolerance-to-pass: no row %s in %s' % (q, summary))
    v, se, t = num(V[q]), num(S[q]), num(theory)
    if isnan_text(V[q]) or isnan_text(S[q]) or t == 0:
        return [Val().row(out)]
    return [Val((abs(v - t) + 2 * se) / abs(t), se / abs(t)).row(out)]


def tab01_projected_cpu_hours(c, p, s):
    """mai-duy-2019/tab01-wavelengths: the paper tier's CPU-hours from a run's cost per
    particle-step c / (p s): 22 runs of 13500 + 6 k^3 particles (k = 3 ... 13), 8000 steps"""
    n = 0.0
    for k in range(3, 14):
        n += 13500 + 6 * k * k * k
    return [cfmt('%.4g', num(c) / (num(p) * num(s)) * 2 * n * 8000 / 3600)]


def tab01_tables(summary, paper1):
    """mai-duy-2019/tab01-wavelengths: Table 1 beside the paper's columns (sphere eq. 32, cube
    eq. 31, TCAF value +- se or "no crossing" with the free - constrained eta(k -> 0), "-" when
    not run) and the TCAF lambda for the plot (nan when absent). Returns (table1, lambda_tcaf)."""
    V, S = summary_dict(summary)
    phi = {}
    for r in rows(summary):
        if fld(r, 1).startswith('phi_k'):
            phi[fld(r, 1)[5:]] = fld(r, 2)

    def tc(q):
        if q not in V:
            return '-'
        if V[q] == 'nan':
            d = 'eta_k0_free_minus_constrained_' + q[12:]
            return cfmt('no crossing (free - constrained eta(k->0) = %.1f +- %.1f)', V.get(d, ''), S.get(d, ''))
        return cfmt('%.3f +- %.3f', V[q], S[q])
    t1 = ['k\tphi\tsphere (eq. 32)\tsphere, paper\tcube (eq. 31)\tcube, paper\tTCAF (sec. 4.2.3)\tTCAF, paper']
    lt_ = []
    for i, r in enumerate(rows(paper1)):
        if i == 0:
            lt_.append('phi\tlambda_tcaf\tse')
        if fld(r, 1).startswith('#') or fld(r, 1) == 'k':
            continue
        k = fld(r, 1)
        tag = cfmt('phi%.4f', phi.get(k, ''))
        t1.append(cfmt('%s\t%.4f\t%.4f\t%s\t%.4f\t%s\t%s\t%s', k, phi.get(k, ''), V.get('lambda_sphere_' + tag, ''), fld(r, 3),
                       V.get('lambda_cube_' + tag, ''), fld(r, 4), tc('lambda_tcaf_' + tag), fld(r, 5)))
        if i > 0:
            q = 'lambda_tcaf_' + tag
            lt_.append(cfmt('%.6f\t%s\t%s', phi.get(k, ''), V[q] if q in V else 'nan', S[q] if q in V else 'nan'))
    return t1, lt_


def r_half(fit_out):
    """mai-duy-2019 fig04's colloid size: where the straight line through g(r) (`dpd fit-line`,
    centred at r = 0.35: value_at_centre, slope) reaches 1/2"""
    v = {}
    for r in fit_out:
        v[fld(r, 1)] = fld(r, 2)
    return [cfmt('%.10g', 0.35 + div(0.5 - num(v.get('value_at_centre', '')), num(v.get('slope', ''))))]


def colloid_radius_rows(r_halves, d):
    """the mean r_half over independent runs and its standard error (mean_se), and the colloid
    radius d + r_half (d exact: the site distance)"""
    o = mean_se(r_halves)
    m = num(o.v)
    return [cfmt('colloid_rdf_r_half\t%.6g\t%.3g', m, o.se), cfmt('colloid_radius_rdf\t%.6g\t%.3g', num(d) + m, o.se)]


def shear_rate_at_pe(summary, pe):
    """the shear rate of a Peclet number: Pe = rate a^3 6 pi eta / kBT (kBT = 1; D0 = kBT /
    (6 pi eta a)), rate = Pe / (6 pi eta a^3); errors of eta and a (3 times a's relative) in
    quadrature (v_rel2)"""
    V, S = summary_dict(summary)
    e, a = num(V.get('eta_solvent', '')), num(V.get('colloid_radius_rdf', ''))
    return [v_rel2(div(num(pe), 6 * 3.14159265358979 * e * a * a * a), V.get('eta_solvent', ''), S.get('eta_solvent', ''),
                   V.get('colloid_radius_rdf', ''), 3 * num(S.get('colloid_radius_rdf', ''))).row('shear_rate_at_paper_pe')]


def lambda_cube(L, k):
    """eq. 31 of Mai-Duy et al. 2019: lambda = L / k (k colloids per axis)"""
    return [cfmt('%.10g', div(num(L), num(k)))]


def lambda_sphere(L, k):
    """eq. 32 of Mai-Duy et al. 2019: lambda = (3 / (4 pi n))^(1/3), n = k^3 / L^3"""
    k, L = num(k), num(L)
    return [cfmt('%.10g', pw(3 / (4 * 3.14159265358979 * pw(k, 3) / pw(L, 3)), 1 / 3))]


def fig04_ratios(summary, t):
    """mai-duy-2019 fig04: eta_r = eta_susp / eta(k) at the cube and sphere k of the free system
    and of the solvent (v_ratio; nan where eta(k) is not), and eta_r(TCAF) - eta_r(original) =
    es / a - es / b with the errors of the shared eta_susp counted once (first order)"""
    V, S = summary_dict(summary)
    out = []

    def r(name, den):
        if den not in V or V[den] == 'nan':
            out.append('%s\tnan\tnan' % name)
            return
        out.append(v_ratio(V.get('eta_susp_' + t, ''), S.get('eta_susp_' + t, ''), V[den], S[den]).row(name))
    r('eta_r_cube_' + t, 'eta_free_cube_' + t)
    r('eta_r_sphere_' + t, 'eta_free_sphere_' + t)
    r('eta_r_cube_solvent_' + t, 'eta_solvent_cube_' + t)
    r('eta_r_sphere_solvent_' + t, 'eta_solvent_sphere_' + t)
    es, a, b = num(V.get('eta_susp_' + t, '')), num(V.get('eta_eff_' + t, '')), num(V.get('eta_solvent', ''))
    d = div(es, a) - div(es, b)
    q = [num(S.get('eta_susp_' + t, '')) * (div(1, a) - div(1, b)), div(es * num(S.get('eta_eff_' + t, '')), sq(a)),
         div(es * num(S.get('eta_solvent', '')), sq(b))]
    out.append(cfmt('eta_r_tcaf_minus_original_%s\t%.10g\t%.4g', t, d, quad(q)))
    return out


def fig04_eta_r_row(summary, t):
    """mai-duy-2019 fig04: the row of eta_r.tsv at one phi (original, TCAF, cube, sphere, cube and
    sphere on the solvent; value se each, nan where absent)"""
    V, S = summary_dict(summary)
    g = lambda q: V[q] + '\t' + S[q] if q in V else 'nan\tnan'
    return [cfmt('%.6f\t%s\t%s\t%s\t%s\t%s\t%s', V.get('phi_' + t, ''), g('eta_r_original_' + t), g('eta_r_tcaf_' + t),
                 g('eta_r_cube_' + t), g('eta_r_sphere_' + t), g('eta_r_cube_solvent_' + t), g('eta_r_sphere_solvent_' + t))]


def wpoly2(xs, ys, ses):
    """weighted (1 / se^2) least-squares parabola y = c0 + c1 x + c2 x^2 by Cramer's rule on the
    normal equations; c0 and its error from the inverse of the normal matrix (chi-square fit with
    known errors; num_wpoly2). Returns Val(c0, c0_se), nan for fewer than 3 points."""
    S, B = [0.0] * 5, [0.0] * 3
    for x, y, e in zip(xs, ys, ses):
        w = div(1.0, sq(e))
        xp = 1.0
        for p in range(5):
            S[p] += w * xp
            if p <= 2:
                B[p] += w * num(y) * xp
            xp *= num(x)
    D = det3(S[0], S[1], S[2], S[1], S[2], S[3], S[2], S[3], S[4])
    if len(xs) < 3 or eq(D, 0):
        return Val()
    return Val(det3(B[0], S[1], S[2], B[1], S[2], S[3], B[2], S[3], S[4]) / D, sqrt((S[2] * S[4] - S[3] * S[3]) / D))


def det3(a11, a12, a13, a21, a22, a23, a31, a32, a33):
    """the determinant of a 3 x 3 matrix by cofactors along the first row (num_det3)"""
    return a11 * (a22 * a33 - a23 * a32) - a12 * (a21 * a33 - a23 * a31) + a13 * (a21 * a32 - a22 * a31)


def uniform_se(lo, hi):
    """the standard deviation of a value known only to lie in [lo, hi]: (hi - lo) / sqrt(12)"""
    return (num(hi) - num(lo)) / sqrt(12)


def cost_per_kilo(cpu, n, t):
    """methods/speed-accuracy: CPU seconds per 1000 particles per time unit"""
    return [cfmt('%.5g', num(cpu) / (num(n) / 1000) / num(t))]


def ladder_cost_per_dt(path):
    """methods/speed-accuracy: each fluid's CPU cost per particle-step averaged over its ladder
    (sum of CPU over sum of particle-steps, the rows in order) times the steps per time unit
    1 / dt, appended to ladder-dt.tsv as cost_per_dt"""
    rs = rows(path)
    c, ps = {}, {}
    for r in rs[1:]:
        if fld(r, 8) != 'nan':
            f = fld(r, 1)
            c[f] = c.get(f, 0.0) + num(fld(r, 8))
            ps[f] = ps.get(f, 0.0) + div(num(fld(r, 8)), num(fld(r, 9))) * 1000 / num(fld(r, 3))
    out = ['\t'.join(rs[0]) + '\tcost_per_dt'] if rs else []
    for r in rs[1:]:
        out.append(cfmt('%s\t%.5g', '\t'.join(r), div(div(c.get(fld(r, 1), 0.0), ps.get(fld(r, 1), 0.0)) * 1000, num(fld(r, 3)))))
    return out


def gw_temperature_ladder(path, big):
    """methods/speed-accuracy, Groot-Warren fluid at lambda = 0.5: (a) T0 of the weighted parabola
    T = T0 + c1 dt + c2 dt^2 (wpoly2; FDT: T0 = kBT); (b) the order of the error, the weighted
    line through (log dt, log |T - 1|) over the points whose |T - 1| exceeds 2 stderr (error of
    log |T - 1| = se / |T - 1|; wline); (c) |T - 1| at lambda 0.65 over that at 0.5 at dt BIG
    (v_ratio)"""
    x, y, s, e, es = [], [], [], {}, {}
    for r in rows(path):
        if fld(r, 1) != 'gw' or fld(r, 4) == 'nan':
            continue
        if eq(fld(r, 2), 0.5):
            x.append(fld(r, 3)); y.append(fld(r, 4)); s.append(fld(r, 5))
        if eq(fld(r, 3), big):
            e[fld(r, 2)] = num(fld(r, 4)) - 1
            es[fld(r, 2)] = fld(r, 5)
    out = []
    o = wpoly2(x, y, s)
    out.append(cfmt('T0_extrapolated_gw_lambda0.5\t%.6g\t%.4g', o.v, o.se))
    X, Y, W = [], [], []
    for xi, yi, si in zip(x, y, s):
        d = num(yi) - 1
        d = -d if lt(d, 0) else d
        if gt(d, 2 * num(si)):
            X.append(log(num(xi))); Y.append(log(d)); W.append(div(num(si), d))
    if len(X) >= 2:
        ln = wline(X, Y, W)
        out.append(cfmt('T_error_order_gw_lambda0.5\t%.6g\t%.4g', ln.slope, ln.slope_se))
        out.append(cfmt('T_error_order_points_gw_lambda0.5\t%d\t0', len(X)))
    ab = lambda v: (-num(v) if lt(v, 0) else v)
    o = v_ratio(ab(e.get('0.65', '')), es.get('0.65', ''), ab(e.get('0.5', '')), es.get('0.5', ''))
    out.append(cfmt('T_error_ratio_gw_l0.65_l0.5_dt%s\t%s', big, o.pair('%.6g', '%.4g')))
    return out


def dt_within_1pct(path):
    """methods/speed-accuracy: per fluid and lambda, the largest dt of the temperature ladder
    (rows in increasing dt) with |T - 1| <= 0.01 + 2 stderr before the first rung that is not,
    and its error as a value uniform between it and that next rung (uniform_se; nan if none).
    A rung with a nan temperature or stderr (unstable) ends the ladder."""
    best, nxt, bad, K = {}, {}, {}, []
    for r in rows(path)[1:]:
        k = fld(r, 1) + '_l' + fld(r, 2)
        d = 1e9 if fld(r, 4) == 'nan' else num(fld(r, 4)) - 1
        d = -d if lt(d, 0) else d
        if k not in best:
            best[k], nxt[k], bad[k] = 0.0, 'inf', 0
            K.append(k)
        # a rung whose T or stderr is nan (unstable) is not within 1 % (the awk this replaced
        # counted it so: mawk's NaN compares equal)
        within = not isnan_text(fld(r, 4)) and not isnan_text(fld(r, 5)) and le(d, 0.01 + 2 * num(fld(r, 5)))
        if within and not bad[k]:
            best[k] = fld(r, 3)
        elif not bad[k]:
            bad[k], nxt[k] = 1, fld(r, 3)
    return [cfmt('dt_T1pct_%s\t%s\t%s', k, best[k], 'nan' if nxt[k] == 'inf' else cfmt('%.3g', uniform_se(best[k], nxt[k])))
            for k in K]


def rel_error(e, es, r, rs):
    """(e - r) / r and its error sqrt(es^2 + (e rs / r)^2) / r (e and r independent)"""
    e, es, r, rs = num(e), num(es), num(r), num(rs)
    return [cfmt('%.6g\t%.4g', div(e - r, r), div(quad([es, div(e, r) * rs]), r))]


def tolerance_summary(path):
    """methods/speed-accuracy: the PCG row at the paper's tolerance 1e-7 (its relative error
    against fig03's paper tier) and PCG's CPU per step at 1e-7 over that at 1e-3"""
    out, a, b = [], '', ''
    for r in rows(path):
        if fld(r, 1) == 'pcg' and fld(r, 2) == '1e-7':
            out.append('eta_rel_error_pcg_1e-7\t%s\t%s' % (fld(r, 5), fld(r, 6)))
            a = fld(r, 8)
        if fld(r, 1) == 'pcg' and fld(r, 2) == '1e-3':
            b = fld(r, 8)
    out.append(cfmt('cpu_per_step_ratio_pcg_1e-7_1e-3\t%.6g\t0', div(num(a), num(b))))
    return out


def true_error_slopes(path):
    """methods/speed-accuracy: per solver, the unweighted line through (log tolerance, log true
    error) over the rows with a positive true error (line); its error 0 for two points"""
    order, X, Y = [], {}, {}
    for r in rows(path)[1:]:
        if gt(fld(r, 9), 0):
            s = fld(r, 1)
            if s not in X:
                order.append(s); X[s], Y[s] = [], []
            X[s].append(log(num(fld(r, 2)))); Y[s].append(log(num(fld(r, 9))))
    out = []
    for s in order:
        ln = line(X[s], Y[s])
        out.append(cfmt('true_error_slope_%s\t%.6g\t%.4g', s, ln.slope, ln.slope_se if len(X[s]) > 2 else 0.0))
    return out


def _profile_bulk(path, bulk, extra=lambda r: True):
    """the rows of a profile.tsv (pos first) with LO <= pos <= HI (BULK = "LO:HI")"""
    lo, hi = bulk.split(':')[:2]
    return [r for r in rows(path) if not (fld(r, 1).startswith('#') or fld(r, 1) == 'pos')
            and ge(fld(r, 1), lo) and le(fld(r, 1), hi) and extra(r)]


def wall_slip(u, g, gs, h):
    """phan-thien-2016 fig03: the mean slip of the two walls U - (v(top) - v(bottom)) / 2 =
    U - rate h / 2, the error the rate's (v_scale)"""
    o = v_scale(g, gs, div(num(h), 2))
    return [cfmt('%.10g\t%.4g', num(u) - num(o.v), o.se)]


def ik_bulk_stress(profile, bulk):
    """phan-thien-2016 fig03: the Irving-Kirkwood shear stress (column 12) averaged over the bulk
    bins, its error the mean of the bins' errors (column 13; fully correlated bins)"""
    rs = _profile_bulk(profile, bulk, lambda r: fld(r, 13) != 'nan')
    return [cfmt('%.10g\t%.4g', mean([fld(r, 12) for r in rs]), mean([fld(r, 13) for r in rs]))]


def bulk_density(profile, bulk):
    """phan-thien-2016 fig03: the density (column 2) averaged over the bulk bins, its error the
    bins' errors in quadrature over their number (bins independent)"""
    rs = _profile_bulk(profile, bulk)
    n = len(rs)
    return [cfmt('%.6f\t%.4g', mean([fld(r, 2) for r in rs]), div(quad([fld(r, 3) for r in rs]), n))]


def first_defined(path, col):
    """the first data row's column COL and COL + 1 where COL is not nan (e.g. the wall bin)"""
    for r in rows(path):
        if fld(r, 1).startswith('#') or fld(r, 1) == 'pos':
            continue
        if fld(r, col) != 'nan':
            return [fld(r, col) + '\t' + fld(r, col + 1)]
    return []


def wall_minus_lees_edwards(summary, rho, rhose, lepair):
    """phan-thien-2016 fig03: eta (walls) - eta (Lees-Edwards at the measured bulk density rho);
    the LE run's density held at rho, so rho's error enters through d eta / d rho ~ 2 eta / rho
    (eta ~ rho^2), with the two viscosities' errors in quadrature"""
    V, S = summary_dict(summary)
    a, sa = V.get('eta', ''), S.get('eta', '')
    L = parse_pair(lepair)
    e = [sa, L.se, 2 * num(L.v) / num(rho) * num(rhose)]
    return [cfmt('%.10g\t%.4g', num(a) - num(L.v), quad(e))]


def _density_map(path):
    """a density map (density_map.tsv: x y density vx vy, a block per grid row after a header) as
    dicts X, Y, N, U, V keyed by (column, row), and the grid's nx, ny"""
    X, Y, N, U, Vv = {}, {}, {}, {}, {}
    row = col = nx = 0
    for i, r in enumerate(rows(path)):
        if i == 0:
            continue
        if r == ['']:
            if col > 0:
                nx = col
                row += 1
            col = 0
            continue
        X[col, row], Y[col, row], N[col, row], U[col, row], Vv[col, row] = (fld(r, 1), fld(r, 2), fld(r, 3), fld(r, 4), fld(r, 5))
        col += 1
    if col > 0:
        nx = col
        row += 1
    return X, Y, N, U, Vv, nx, row


def _outside(X, Y, i, j, L, cx, cy, rex):
    """bin (i, j)'s centre lies at least rex from (cx, cy), minimum image in a box of side L"""
    g = lambda a, k: num(a.get(k, ''))
    ddx = g(X, (i, j)) - cx
    ddy = g(Y, (i, j)) - cy
    ddx -= L * float(int(ddx / L * 2))          # minimum image (|d| < L); awk's int() truncates
    ddy -= L * float(int(ddy / L * 2))
    return ddx * ddx + ddy * ddy >= rex * rex


def density_fields(path, L, cx, cy, rex, n0):
    """phan-thien-2016 fig08, eq. 49: the density residual sqrt(sum (n - n0)^2) / nb and the mean
    |div u| (central differences, periodic) over the nb bins of a density map whose centre lies at
    least rex from the cylinder centre (cx, cy), minimum image in a box of side L (formerly fields.awk)"""
    L, cx, cy, rex, n0 = num(L), num(cx), num(cy), num(rex), num(n0)
    X, Y, N, U, Vv, nx, ny = _density_map(path)
    dx, dy = div(L, nx), div(L, ny)
    nb, ss, sdiv = 0, 0.0, 0.0
    g = lambda a, k: num(a.get(k, ''))
    for j in range(ny):
        for i in range(nx):
            if not _outside(X, Y, i, j, L, cx, cy, rex):
                continue
            ip, im, jp, jm = (i + 1) % nx, (i + nx - 1) % nx, (j + 1) % ny, (j + ny - 1) % ny
            dv = div(g(U, (ip, j)) - g(U, (im, j)), 2 * dx) + div(g(Vv, (i, jp)) - g(Vv, (i, jm)), 2 * dy)
            ss += sq(g(N, (i, j)) - n0)
            sdiv += -dv if dv < 0 else dv
            nb += 1
    return [cfmt('%.10g\t%.10g\t%d', div(sqrt(ss), nb), div(sdiv, nb), nb)]


def residual_floor_free(q, L, cx, cy, rex, n0, *paths):
    """phan-thien-2016 fig08, a second estimator of eq. 49's residual, free of the statistical floor.
    A run's time-averaged density is the true field plus noise, so sum (n - n0)^2 over the bins
    carries the noise's variance too: a floor that falls with the run length, and that makes the
    plain residual's growth with P depend on the run length. The product (n_a - n0)(n_b - n0) of two
    independent runs a and b has the true field's square as its mean, noise and all. Here
    C = the mean over the pairs of runs of sum (n_a - n0)(n_b - n0), the residual sqrt(C) / nb
    (0 if C < 0), its error the jackknife over the runs (each left out in turn: the pairs of the
    others; Efron & Tibshirani 1993, ch. 11). The bins as density_fields's. Needs 3 runs or more.
    Row "Q<TAB>value<TAB>stderr"."""
    L, cx, cy, rex, n0 = num(L), num(cx), num(cy), num(rex), num(n0)
    if len(paths) < 3:
        raise SystemExit('analysis.py residual-floor-free: %d runs given, the jackknife needs 3 or more' % len(paths))
    dev = []
    for p in paths:
        X, Y, N, U, Vv, nx, ny = _density_map(p)
        dev.append([num(N.get((i, j), '')) - n0 for j in range(ny) for i in range(nx)
                    if _outside(X, Y, i, j, L, cx, cy, rex)])
    nb = len(dev[0])
    if any(len(d) != nb for d in dev):
        raise SystemExit('analysis.py residual-floor-free: the maps keep different numbers of bins')

    def residual(runs):
        c = mean([sum(a * b for a, b in zip(dev[r], dev[s])) for k, r in enumerate(runs) for s in runs[k + 1:]])
        return div(sqrt(c), nb) if c > 0 else 0.0
    n = len(dev)
    jk = jackknife_se([residual([r for r in range(n) if r != left]) for left in range(n)])
    return [Val(residual(list(range(n))), jk.se).row(q)]


def fields_mean_row(P, m, lines):
    """phan-thien-2016 fig08: per pressure and mass, the mean and standard error over the seeds
    (mean_se) of the residual, |div u| and the fluid velocity (rows: residual divu nb U)"""
    r = [l.split('\t') for l in lines]
    out = '%s\t%s' % (P, m)
    for c in (1, 2, 4):
        out += '\t' + mean_se([fld(x, c) for x in r]).pair('%.6g', '%.3g')
    return [out]


def force_balance(q, P, pair):
    """phan-thien-2016 fig08: the drag on the cylinder over the driving force 144 P (the fluid's
    N P for N = 144 per unit length) minus 1 (v_div)"""
    x = parse_pair(pair)
    o = v_div(x.v, x.se, 144 * num(P))
    o.v = num(o.v) - 1
    return [o.row(q)]


def eos_slope(lo, hi):
    """phan-thien-2016 fig08: c_T^2 = dp/dn (mass 1) by the central difference of the pressure at
    n = 137 / 36 and 151 / 36 (v_diff, v_div)"""
    a, b = parse_pair(lo), parse_pair(hi)
    dn = (151 - 137) / 36.0
    o = v_diff(b.v, b.se, a.v, a.se)
    return [v_div(o.v, o.se, dn).pair()]


def fig08_mach(fields, c2):
    """phan-thien-2016 fig08: the Mach number U / c_T of the m = 1 rows, c_T = sqrt(c_T^2)
    (v_sqrt, v_ratio)"""
    x = parse_pair(c2)
    cs = v_sqrt(x.v, x.se)
    return [fld(r, 1) + '\t' + v_ratio(fld(r, 7), fld(r, 8), cs.v, cs.se).pair('%.6g', '%.3g')
            for r in rows(fields)[1:] if eq(fld(r, 2), 1)]


def fig08_growths(fields):
    """phan-thien-2016 fig08: the growth of the residual and of |div u| from P = 0.1 to 1.0 per
    mass, and m = 1's growth over m = 0's (v_ratio)"""
    R, D = {}, {}
    for r in rows(fields)[1:]:
        if fld(r, 1) in ('0.1', '1.0'):
            R[fld(r, 2), fld(r, 1)] = (fld(r, 3), fld(r, 4))
            D[fld(r, 2), fld(r, 1)] = (fld(r, 5), fld(r, 6))
    G, out = {}, []

    def ratio(q, a, b):
        o = v_ratio(a[0], a[1], b[0], b[1])
        G[q] = (o.v, o.se)
        out.append(cfmt('%s\t%.6g\t%.3g', q, o.v, o.se))
    for m in ('0', '1'):
        ratio('residual_growth_m' + m, R.get((m, '1.0'), ('', '')), R.get((m, '0.1'), ('', '')))
        ratio('divu_growth_m' + m, D.get((m, '1.0'), ('', '')), D.get((m, '0.1'), ('', '')))
    ratio('residual_growth_ratio_m1_m0', G['residual_growth_m1'], G['residual_growth_m0'])
    ratio('divu_growth_ratio_m1_m0', G['divu_growth_m1'], G['divu_growth_m0'])
    return out


def dt_scan(summary, dts, out):
    """phan-thien-2016 m0-limit-timestep: per time step of the m = 0 run, its shear rate, eta and
    largest bulk density deviation, appended to OUT with ok = eta within 10 % of the smallest
    step's and the density deviation below 10 %; returns dt_max_sound, the largest step before
    the first that is not ok"""
    V, S = summary_dict(summary)
    D = dts.split()
    e0 = V.get('eta_dt' + D[0], '')
    best, bad, lines = D[0], 0, []
    for d in D:
        e, dd = V.get('eta_dt' + d, ''), V.get('density_bulk_max_rel_dev_dt' + d, '')
        r = div(num(e), num(e0))
        ok = gt(r, 0.9) and lt(r, 1.1) and lt(dd, 0.1)
        if ok and bad == 0:
            best = d
        if not ok:
            bad = 1
        lines.append(cfmt('%s\t%s\t%s\t%s\t%s\t%s\t%d', d, V.get('shear_rate_dt' + d, ''), S.get('shear_rate_dt' + d, ''),
                          e, S.get('eta_dt' + d, ''), dd, 1 if ok else 0))
    with open(out, 'a') as f:
        f.write(''.join(l + '\n' for l in lines))
    return ['dt_max_sound\t%s\t0' % best]


def thinning_row(r, a, D, e, e0):
    """phan-thien-2016 fig13: one row of thinning.tsv: the rate, its Peclet number rate a^2 / D,
    the suspension's and the solvent's viscosity and their ratio eta_r (v_ratio)"""
    x, y = parse_pair(e), parse_pair(e0)
    o = v_ratio(x.v, x.se, y.v, y.se)
    return [cfmt('%s\t%.6g\t%.8g\t%.4g\t%.8g\t%.4g\t%.8g\t%.4g', r, num(r) * num(a) * num(a) / num(D), x.v, x.se, y.v, y.se, o.v, o.se)]


def significance(summary, q, name):
    """(ratio - 1) / stderr of the summary rows named Q: how many standard errors a ratio lies
    from 1"""
    return [cfmt('%s\t%.6g\t0', name, div(num(fld(r, 2)) - 1, num(fld(r, 3)))) for r in rows(summary) if fld(r, 1) == q]


def relative_thinning(path, lo, hi):
    """phan-thien-2016 fig13: eta_r at the lowest rate over eta_r at the highest (v_ratio; the
    last row of each rate)"""
    a = b = ('', '')
    for r in rows(path)[1:]:
        if eq(fld(r, 1), lo):
            a = (fld(r, 7), fld(r, 8))
        if eq(fld(r, 1), hi):
            b = (fld(r, 7), fld(r, 8))
    return [v_ratio(a[0], a[1], b[0], b[1]).row('relative_thinning_ratio')]


def within_1pct_best(tpair, dt, best):
    """mai-duy-2019 solvent-timestep: the larger of BEST and DT if the temperature T +- se is
    within 1 % of kBT = 1 with 3 stderr allowed (|T - 1| <= 0.01 + 3 se), else BEST"""
    t = parse_pair(tpair)
    x = num(t.v) - 1
    if lt(x, 0):
        x = -x
    return [dt if le(x, 0.01 + 3 * num(t.se)) and gt(dt, best) else best]


def abs_max(lo, hi):
    """the larger of |lo| and |hi| (%.10g): a range's amplitude"""
    a, b = num(lo), num(hi)
    a = -a if lt(lo, 0) else a
    b = -b if lt(hi, 0) else b
    return [cfmt('%.10g', a if gt(a, b) else b)]


def mean_list(q, values):
    """Q's mean and standard error over independent runs (mean_se), 0 for a single run"""
    o = mean_se(values)
    if len(values) == 1:
        o.se = 0.0
    return [o.row(q)]


def fig12_row(k, e, e0, es):
    """phan-thien-2016 fig12: one row of eta_r.tsv: k colloids of 3 particles among 144, phi =
    3 k / (144 + 3 k), eta, eta_r = eta / eta_0 (v_ratio), eta_r - 1 and the spring viscosity"""
    a, b, c = parse_pair(e), parse_pair(e0), parse_pair(es)
    kk = num(k)
    phi = 3 * kk / (144 + 3 * kk)
    o = v_ratio(a.v, a.se, b.v, b.se)
    return [cfmt('%d\t%.6g\t%.8g\t%.4g\t%.8g\t%.4g\t%.8g\t%.6g\t%.4g', kk, phi, a.v, a.se, o.v, o.se, num(o.v) - 1, c.v, c.se)]


def slope_rows(fit, name):
    """`dpd fit-line` output: its slope as NAME and its chi2_dof as NAME_chi2_dof, in file order"""
    out = []
    for r in rows(fit):
        if fld(r, 1) == 'slope':
            out.append('%s\t%s\t%s' % (name, fld(r, 2), fld(r, 3)))
        if fld(r, 1) == 'chi2_dof':
            out.append('%s_chi2_dof\t%s\t0' % (name, fld(r, 2)))
    return out


def fig07_drag(P, N, h, drag, U, eta, a):
    """phan-thien-2016 fig07, eq. 47 (Hasimoto's periodic array of cylinders): F_H = 4 pi eta U /
    (ln(h / a) - 1.3105); rows force_balance_P (drag / (N P) - 1), hasimoto_ratio_P (drag / F_H,
    relative errors of U, eta and a in quadrature) and hydrodynamic_radius_P (the a that makes
    eq. 47 exact: h exp(-(x + 1.3105)), x = 4 pi eta U / drag, errors of U and eta); and the row
    of drag.tsv (returned second)"""
    D, V, E, A = parse_pair(drag), parse_pair(U), parse_pair(eta), parse_pair(a)
    d1, d2, v1, v2, e1, e2, a1, a2 = (num(x) for x in (D.v, D.se, V.v, V.se, E.v, E.se, A.v, A.se))
    pi = math.atan2(0, -1)
    den = log(num(h) / a1) - 1.3105                        # eq. 47
    FH = div(4 * pi * e1 * v1, den)
    r = [div(v2, v1), div(e2, e1), div(a2, a1 * den)]
    rel = quad(r)
    out = []
    o = v_div(D.v, D.se, num(N) * num(P))
    o.v = num(o.v) - 1
    out.append(o.row('force_balance_P' + P))
    out.append(v_relerr(div(d1, FH), r).row('hasimoto_ratio_P' + P))
    x = div(4 * pi * e1 * v1, d1)
    ah = num(h) * exp(-(x + 1.3105))
    o = v_relerr(ah * x, r[:2])
    out.append(cfmt('hydrodynamic_radius_P%s\t%.10g\t%.4g', P, ah, o.se))
    return out, [cfmt('%s\t%g\t%g\t%g\t%g\t%g\t%g', P, D.v, D.se, V.v, V.se, FH, FH * rel)]


def v_relerr(x, rels):
    """x with the relative errors rels in quadrature (num_relerr)"""
    for r in rels:
        if _nan4(x, r):
            return Val()
    return Val(num(x), abs(num(x)) * quad(rels))


def solvent_radius(rdf, threshold='0.001', half_bin='0.005'):
    """phan-thien-2016 fig10-11: the solvent's closest approach to a colloid: the first r (bin
    centre less half a bin) where the colloid-solvent g(r) reaches THRESHOLD"""
    for r in rows(rdf)[1:]:
        if ge(fld(r, 2), num(threshold)):
            return [cfmt('solvent_radius\t%.6g\t0', num(fld(r, 1)) - num(half_bin))]
    return []


def values(lines, names):
    """the value (column 2) of the last row of each name, tab-joined ("" if absent)"""
    v = {}
    for l in lines:
        r = l.split('\t')
        v[fld(r, 1)] = fld(r, 2)
    return ['\t'.join(v.get(n, '') for n in names)]


def project(x, w):
    """the amplitude of x along w, sum x w / sum w^2 ("nan" for w = 0; num_project)"""
    sxw = sww = 0.0
    for a, b in zip(x, w):
        a, b = num(a), num(b)
        sxw += a * b
        sww += b * b
    return 'nan' if eq(sww, 0) else sxw / sww


def couette_growth(lines, ts, name, out):
    """phan-thien-2016 fig04: the start-up of the Couette profile from the per-block profiles of
    independent runs (rows block t pos vx, each run after its header). a(t) = sum_y v(y,t)
    v_s(y) / sum_y v_s(y)^2, the projection on the steady profile v_s (the run-averaged profile
    over the blocks with t >= TS); t90 the first time a reaches 0.9, linear between block times
    from a = 0 at t = 0; its error by the jackknife over the runs (jackknife_se). Writes
    growth_NAME.tsv and profiles_NAME.tsv (profiles nearest t = 2, 4, ..., 20 and the steady one)
    into OUT; returns the t90_NAME row (formerly growth.awk)."""
    ts = num(ts)
    v, t, Y, seen = {}, {}, [], set()
    S = nb = 0
    for l in lines:
        r = l.split('\t')
        if fld(r, 1) == 'block':
            S += 1
            continue
        if fld(r, 4) in ('nan', ''):
            continue
        b, y = int(num(fld(r, 1))), fld(r, 3)
        v[S, b, y] = fld(r, 4)
        t[b] = fld(r, 2)
        if b > nb:
            nb = b
        if y not in seen:
            seen.add(y)
            Y.append(y)
    ny = len(Y)
    tb = lambda b: t.get(b, '')

    def profile(b, ex):
        return [mean([v.get((s, b, Y[j]), '') for s in range(1, S + 1) if s != ex]) for j in range(ny)]
    steady, prof = [], {}

    def growth(ex):
        vs = [0.0] * ny
        n = 0
        for b in range(nb + 1):
            if ge(tb(b), ts):
                n += 1
                m = profile(b, ex)
                for j in range(ny):
                    vs[j] += num(m[j])
        vs = [div(x, float(n)) for x in vs]
        if not ex:
            steady[:] = vs
        a = {}
        for b in range(nb + 1):
            m = profile(b, ex)
            a[b] = project(m, vs)
            if not ex:
                for j in range(ny):
                    prof[b, j] = m[j]
        return a

    def t90(a):
        ap, tp = 0.0, 0.0
        for b in range(nb + 1):
            if ge(a[b], 0.9) and lt(ap, 0.9):
                return num(tp) + (num(tb(b)) - num(tp)) * div(0.9 - num(ap), num(a[b]) - num(ap))
            ap, tp = a[b], tb(b)
        return -1.0
    a = growth(0)
    full = t90(a)
    with open(os.path.join(out, 'growth_%s.tsv' % name), 'w') as f:
        f.write('t\ta\n' + ''.join('%s\t%s\n' % (tb(b), astr(a[b])) for b in range(nb + 1)))
    pick, hdr = {}, 'pos'
    for k in range(2, 21, 2):
        best = 0
        for b in range(nb + 1):
            if pw(num(tb(b)) - k, 2) < pw(num(tb(best)) - k, 2):
                best = b
        pick[k] = best
        hdr += '\tt%d' % k
    ordr = list(range(ny))
    for i in range(ny):
        for j in range(i + 1, ny):
            if num(Y[ordr[j]]) + 0 < num(Y[ordr[i]]) + 0:
                ordr[i], ordr[j] = ordr[j], ordr[i]
    with open(os.path.join(out, 'profiles_%s.tsv' % name), 'w') as f:
        f.write(hdr + '\tsteady\n')
        for i in range(ny):
            line = astr(num(Y[ordr[i]]) + 0)
            for k in range(2, 21, 2):
                line += '\t' + astr(prof.get((pick[k], ordr[i]), ''))
            f.write(line + '\t' + astr(steady[ordr[i]]) + '\n')
    se = 0.0
    if S > 1:
        tj = [t90(growth(s)) for s in range(1, S + 1)]
        se = jackknife_se(tj).se
    return [cfmt('t90_%s\t%.6g\t%.4g', name, full, se)]


# ---------------------------------------------------------------- methods/stability-map

def bisect_seed_row(f, p, v, seed, a, b):
    """methods/stability-map: a seed's row of dt-max-seeds.tsv: the geometric middle of its last
    bracket [a, b] (nan if the bisection reached an end: b = inf or a = 0)"""
    mid = 'nan' if b == 'inf' or eq(a, 0) else cfmt('%.6g', sqrt(num(a) * num(b)))
    return ['\t'.join([f, p, v, seed, mid, a, b])]


def bisect_dt_max(f, p, v, res):
    """methods/stability-map: a family's dt_max at one parameter value over the seeds' final
    brackets RES ("lo:hi ..."): the mean of the brackets' geometric middles (mean_se), its error
    the seeds' scatter and the brackets' resolution (uniform_se) in quadrature, a bracket shared by
    n_b of n seeds counted once with weight n_b / n (README "shared-bracket rule"); nan when a
    bisection reached an end"""
    R = res.split()
    lo, hi, d, e, K, nb, eb = [], [], [], [], [], {}, {}
    L = H = None
    bad = False
    for r in R:
        b = r.split(':')
        lo.append(b[0]); hi.append(b[1] if len(b) > 1 else '')
        if hi[-1] == 'inf' or eq(lo[-1], 0):
            bad = True
            continue
        d.append(sqrt(num(lo[-1]) * num(hi[-1])))
        e.append(uniform_se(lo[-1], hi[-1]))
        L = lo[-1] if L is None or lt(lo[-1], L) else L
        H = hi[-1] if H is None or gt(hi[-1], H) else H
        if r not in nb:
            K.append(r)
        nb[r] = nb.get(r, 0) + 1
        eb[r] = e[-1]
    if bad:
        return ['%s\t%s\t%s\tnan\tnan\t%s\t%s' % (f, p, v, lo[0], hi[0])]
    n = len(R)
    o = mean_se(d)
    if n > 1:
        w = [nb[k] * eb[k] for k in K]
        se = quad([o.se, quad(w) / n])
    else:
        se = e[0]
    return [cfmt('%s\t%s\t%s\t%.5g\t%.3g\t%s\t%s', f, p, v, o.v, se, L if L is not None else '', H if H is not None else '')]


def _family_rows(path, f, lo, hi, extra):
    return [r for r in rows(path) if fld(r, 1) == f and ge(num(fld(r, 3)), lo) and le(num(fld(r, 3)), hi) and extra(r)]


def dt_max_slope(path, q, f, a, b):
    """methods/stability-map: the exponent of dt_max against the parameter over [a, b]: the
    weighted line through (ln x, ln dt_max), the error of ln dt_max dt_max's relative error (wline)"""
    rs = _family_rows(path, f, a, b, lambda r: fld(r, 4) != 'nan')
    if len(rs) < 2:
        return ['%s\tnan\tnan' % q]
    ln = wline([log(num(fld(r, 3))) for r in rs], [log(num(fld(r, 4))) for r in rs],
               [div(num(fld(r, 5)), num(fld(r, 4))) for r in rs])
    return [cfmt('%s\t%.5g\t%.3g', q, ln.slope, ln.slope_se)]


def _correction(x, q):
    """x^q of the leading correction to scaling (sqrt, 1 / sqrt, 1 / x written out, as the fit's
    rule states them)"""
    if eq(q, 0.5):
        return sqrt(x)
    if eq(q, -0.5):
        return div(1, sqrt(x))
    if eq(q, -1):
        return div(1, x)
    return exp(num(q) * log(x))


def dt_max_corrected(path, f, lo, hi, q, qp, qb, qc):
    """methods/stability-map, README "The corrected exponents": ln dt_max = ln C + p ln x + beta x^q
    by weighted least squares (weights 1 / (se / dt_max)^2; Cramer's rule on the 3 x 3 normal
    equations), p's and beta's errors from the inverse normal matrix, chi^2 / (n - 3) beside them;
    nan for fewer than 4 points"""
    rs = _family_rows(path, f, lo, hi, lambda r: usable(fld(r, 4), fld(r, 5)))
    n = len(rs)
    if n < 4:
        return ['%s\tnan\tnan' % qp, '%s\tnan\tnan' % qb, '%s\tnan\t0' % qc]
    x1 = [log(num(fld(r, 3))) for r in rs]
    x2 = [_correction(num(fld(r, 3)), q) for r in rs]
    y = [log(num(fld(r, 4))) for r in rs]
    w = [div(1, sq(div(num(fld(r, 5)), num(fld(r, 4))))) for r in rs]
    S00 = S01 = S02 = S11 = S12 = S22 = b0 = b1 = b2 = 0.0
    for i in range(n):
        S00 += w[i]; S01 += w[i] * x1[i]; S02 += w[i] * x2[i]; S11 += w[i] * x1[i] * x1[i]; S12 += w[i] * x1[i] * x2[i]
        S22 += w[i] * x2[i] * x2[i]
        b0 += w[i] * y[i]; b1 += w[i] * x1[i] * y[i]; b2 += w[i] * x2[i] * y[i]
    D = det3(S00, S01, S02, S01, S11, S12, S02, S12, S22)
    c = div(det3(b0, S01, S02, b1, S11, S12, b2, S12, S22), D)
    p = div(det3(S00, b0, S02, S01, b1, S12, S02, b2, S22), D)
    be = div(det3(S00, S01, b0, S01, S11, b1, S02, S12, b2), D)
    vp, vb = div(S00 * S22 - S02 * S02, D), div(S00 * S11 - S01 * S01, D)
    chi2 = 0.0
    for i in range(n):
        chi2 += w[i] * sq(y[i] - c - p * x1[i] - be * x2[i])
    return [cfmt('%s\t%.5g\t%.3g', qp, p, sqrt(vp)), cfmt('%s\t%.4g\t%.3g', qb, be, sqrt(vb)), cfmt('%s\t%.4g\t0', qc, chi2 / (n - 3))]


def dt_max_paired(path, f, lo, hi, q, name):
    """methods/stability-map, README "The paired exponents" and "The far windows": per seed, the
    corrected form ln dt_max = ln C + p ln x + beta x^q and the pure power law fitted unweighted
    through its dt_max over [lo, hi]; p = the mean over the seeds, stat = sqrt(sd^2 / n + res^2)
    with res the bisection's resolution carried through each seed's fit (p = sum c_i ln dt_i,
    res^2 = sum c_i^2 ln(hi_i / lo_i)^2 / 12) averaged over the seeds, model = |p_corrected -
    p_pure|. Rows NAME (stat and model in quadrature), NAME_stat, NAME_pure, NAME_model,
    NAME_resolution"""
    seeds, X1, X2, Y, V = [], {}, {}, {}, {}
    for r in rows(path)[1:]:
        if fld(r, 1) == f and ge(num(fld(r, 3)), lo) and le(num(fld(r, 3)), hi) and not isnan_text(fld(r, 5)):
            s = fld(r, 4)
            if s not in X1:
                seeds.append(s); X1[s], X2[s], Y[s], V[s] = [], [], [], []
            x = num(fld(r, 3))
            X1[s].append(log(x)); Y[s].append(log(num(fld(r, 5))))
            V[s].append(sq(log(div(num(fld(r, 7)), num(fld(r, 6))))) / 12)
            X2[s].append(_correction(x, q))
    ns = len(seeds)
    if ns < 2:
        return ['%s\tnan\tnan' % name]
    pc, pp = [], []
    rc = rp = 0.0
    for s in seeds:
        n = len(X1[s])
        if n < 4:
            return ['%s\tnan\tnan' % name]
        S00 = S01 = S02 = S11 = S12 = S22 = b0 = b1 = b2 = 0.0
        for x1, x2, y in zip(X1[s], X2[s], Y[s]):
            S00 += 1; S01 += x1; S02 += x2; S11 += x1 * x1; S12 += x1 * x2; S22 += x2 * x2; b0 += y; b1 += x1 * y; b2 += x2 * y
        D = det3(S00, S01, S02, S01, S11, S12, S02, S12, S22)
        D2 = S00 * S11 - S01 * S01
        pc.append(div(det3(S00, b0, S02, S01, b1, S12, S02, b2, S22), D))
        pp.append(div(S00 * b1 - S01 * b0, D2))
        vc = vp = 0.0
        for x1, x2, v in zip(X1[s], X2[s], V[s]):
            vc += sq(div(det3(S00, 1, S02, S01, x1, S12, S02, x2, S22), D)) * v
            vp += sq(div(S00 * x1 - S01, D2)) * v
        rc += sqrt(vc) / ns
        rp += sqrt(vp) / ns
    c, p = mean_se(pc), mean_se(pp)
    stc = quad([c.se, rc])
    e2 = num(c.v) - num(p.v)
    e2 = -e2 if e2 < 0 else e2
    return [cfmt('%s\t%.5g\t%.3g', name, c.v, quad([stc, e2])), cfmt('%s_stat\t%.5g\t%.3g', name, c.v, stc),
            cfmt('%s_pure\t%.5g\t%.3g', name, p.v, quad([p.se, rp])), cfmt('%s_model\t%.3g\t0', name, e2),
            cfmt('%s_resolution\t%.3g\t0', name, rc)]


def _last_pair(path, f, v):
    a = ('', '')
    for r in rows(path):
        if fld(r, 1) == f and eq(fld(r, 3), v):
            a = (fld(r, 4), fld(r, 5))
    return a


def dt_max_ratio_row(path, q, f1, v1, f2, v2):
    """methods/stability-map: dt_max of (f1, v1) over that of (f2, v2) (v_ratio)"""
    a, b = _last_pair(path, f1, v1), _last_pair(path, f2, v2)
    return [q + '\t' + v_ratio(a[0], a[1], b[0], b[1]).pair('%.5g', '%.3g')]


def gas_weight_ratio(path, g):
    """methods/stability-map: dt_max at s = 2 over s = 0.5 (ideal gas at gamma = g; v_ratio) and
    the ratio of the ideal gas's mean sum_j w_D, 4 pi n int_0^1 r^2 (1 - r)^s dr = 8 pi n / ((s + 1)
    (s + 2) (s + 3)), at s = 0.5 over s = 2"""
    out = dt_max_ratio_row(path, 'dt_max_ratio_s2_s0.5_gas_gamma' + g, 'gas_s2', g, 'gas_s0.5', g)
    w2, w05 = 2 / (3 * 4 * 5), 2 / (1.5 * 2.5 * 3.5)
    return out + [cfmt('sum_wD_ratio_s0.5_s2_ideal_gas\t%.5g\t0', w05 / w2)]


def family_rows(path):
    """methods/stability-map, what paper.md reads off the families: dt_max / m per mass (v_div),
    dt_max sqrt(a) per repulsion (v_scale) and the local exponent ln(dt_2 / dt_1) / ln(a_2 / a_1)
    between neighbouring a (relative errors in quadrature over ln(a_2 / a_1))"""
    out, a, d, s = [], [], [], []
    for r in rows(path):
        if fld(r, 1) == 'a_gamma4.5':
            a.append(fld(r, 3)); d.append(fld(r, 4)); s.append(fld(r, 5))
        if fld(r, 1) == 'mass':
            out.append('dt_max_over_m_m%s\t%s' % (fld(r, 3), v_div(fld(r, 4), fld(r, 5), fld(r, 3)).pair('%.5g', '%.3g')))
    for i in range(len(a)):
        out.append('dt_max_sqrt_a_a%s\t%s' % (a[i], v_scale(d[i], s[i], sqrt(num(a[i]))).pair('%.5g', '%.3g')))
    for i in range(1, len(a)):
        l = log(div(num(a[i]), num(a[i - 1])))
        r = [div(num(s[i]), num(d[i])), div(num(s[i - 1]), num(d[i - 1]))]
        out.append(cfmt('dt_max_local_exponent_a%s_%s\t%.5g\t%.3g', a[i - 1], a[i], div(log(div(num(d[i]), num(d[i - 1]))), l),
                        div(quad(r), l)))
    return out


def trial_rows(path):
    """methods/stability-map: the fraction of unstable trials that stopped with a proper message
    (column 8, "-" for a stable trial), their count, and the count of all trials"""
    rs = rows(path)
    n, ok = 0, 0.0
    for r in rs[1:]:
        if fld(r, 8) != '-':
            n += 1
            ok += num(fld(r, 8))
    return [cfmt('blowup_message_ok_fraction\t%.6g\t0', div(ok, float(n))), cfmt('unstable_trials\t%d\t0', n),
            cfmt('trials\t%d\t0', len(rs) - 1)]


def cpu_from_times(path):
    """the shell's `times` (second line: the children's user and system time, XmY.YYYs) in seconds"""
    r = rows(path)[1][0].split() if len(rows(path)) > 1 else ['', '']
    a, b = (r[0] if r else '').split('m'), (r[1] if len(r) > 1 else '').split('m')
    g = lambda x, i: num(x[i]) if i < len(x) else 0.0
    return [cfmt('%.3f', g(a, 0) * 60 + g(a, 1) + g(b, 0) * 60 + g(b, 1))]


def equal_error(path, estar, solvers=('scheme1', 'scheme2_paper', 'scheme2_consistent', 'pcg', 'pcg_2level')):
    """phan-thien-2016 fig02-equal-error: each solver's iterations and CPU per step at the true
    relative error E*, interpolated linearly in log E between the two rungs of its tolerance ladder
    that bracket log E* most tightly (or the two nearest when E* lies outside: extrapolated), errors
    by v_lin2; then the ratios of issue 3 (v_ratio) and whether the two-level PCG is the best"""
    n, lg, it, its, cs, css = {}, {}, {}, {}, {}, {}
    for r in rows(path)[1:]:
        s = fld(r, 1)
        n[s] = n.get(s, 0) + 1
        k = n[s]
        lg[s, k] = log(num(fld(r, 5)))
        it[s, k], its[s, k], cs[s, k], css[s, k] = fld(r, 3), fld(r, 4), fld(r, 6), fld(r, 7)
    lE = log(num(estar))
    extrap = {}
    L = lambda s, k: lg.get((s, k), 0.0)

    def interp(s, a, as_):
        i1 = i2 = 0
        m = n.get(s, 0)
        for k in range(1, m + 1):
            for j in range(1, m + 1):
                if k != j and ge(L(s, k), lE) and le(L(s, j), lE) and (i1 == 0 or lt(L(s, k) - L(s, j), L(s, i1) - L(s, i2))):
                    i1, i2 = k, j
        if i1 == 0:
            extrap[s] = 1
            i1, i2 = 1, 2
            for k in range(1, m + 1):
                if pw(L(s, k) - lE, 2) < pw(L(s, i1) - lE, 2):
                    i1 = k
            for k in range(1, m + 1):
                if k != i1 and (i2 == i1 or pw(L(s, k) - lE, 2) < pw(L(s, i2) - lE, 2)):
                    i2 = k
        w = 0.5 if eq(L(s, i1), L(s, i2)) else div(lE - L(s, i2), L(s, i1) - L(s, i2))
        return v_lin2(w, a.get((s, i1), ''), as_.get((s, i1), ''), 1 - w, a.get((s, i2), ''), as_.get((s, i2), ''))
    out, I, C = [], {}, {}
    bi = bt = ''
    for s in solvers:
        I[s] = interp(s, it, its)
        C[s] = interp(s, cs, css)
        out.append(cfmt('iterations_at_Estar_%s\t%.6g\t%.4g', s, I[s].v, I[s].se))
        out.append(cfmt('cpu_seconds_at_Estar_%s\t%.6g\t%.4g', s, C[s].v, C[s].se))
        if extrap.get(s):
            out.append('extrapolated_%s\t1\t0' % s)
        if bi == '' or lt(I[s].v, I[bi].v):
            bi = s
        if bt == '' or lt(C[s].v, C[bt].v):
            bt = s

    def ratio(q, v, a, b):
        out.append(q + '\t' + v_ratio(v[a].v, v[a].se, v[b].v, v[b].se).pair('%.6g', '%.4g'))
    ratio('iteration_ratio_scheme2_best', I, 'scheme2_paper', bi)
    ratio('time_ratio_scheme1_best', C, 'scheme1', bt)
    ratio('iteration_ratio_scheme1_scheme2', I, 'scheme1', 'scheme2_paper')
    ratio('cpu_ratio_scheme1_scheme2_at_Estar', C, 'scheme1', 'scheme2_paper')
    out.append('best_iterations_is_pcg_2level\t%d\t0' % (bi == 'pcg_2level'))
    out.append('best_time_is_pcg_2level\t%d\t0' % (bt == 'pcg_2level'))
    return out


# ---------------------------------------------------------------- pan-2008 (Pan, Caswell & Karniadakis 2008)
# Each formula is the paper's equation as the run.sh's awk evaluated it (same association, powers by
# the C library's pow() as mawk's ^), so the committed tables keep their bytes.

PI = 3.141592653589793


def table_rows(path, suffix=''):
    """the rows after a table's header, as summary rows (selection, no arithmetic); with SUFFIX
    their first three columns, the name suffixed (fluid-viscosity: the fit at dt = 0.01)"""
    rs = rows(path)[1:]
    if not suffix:
        return ['\t'.join(r) for r in rs]
    return [fld(r, 1) + suffix + '\t' + fld(r, 2) + '\t' + fld(r, 3) for r in rs]


def mean_runs(lines):
    """the equal-weight mean of runs of equal length ("value<TAB>stderr" lines): the mean of the
    values, its error sqrt(sum se^2) / n (independent runs; the runs' own errors, not their
    scatter, which two or three runs would give poorly)"""
    xs = [l.split('\t')[0] for l in lines]
    es = [fld(l.split('\t'), 2) for l in lines]
    return Val(mean(xs), div(quad(es), len(xs)))


def column_mean_se(path, col):
    """the mean of column COL over the rows after the header and its standard error, the rows as
    independent samples (blocks of a series, replicas' blocks; mean_se)"""
    return mean_se([fld(r, col) for r in rows(path)[1:]])


def noise_row(name, se, t, dof):
    """a torque's noise intensity: the variance of a mean times the production time it took,
    v = se^2 t (torque^2 x time: what sets every projected run length), with the relative
    standard error of a variance estimated from DOF + 1 blocks, sqrt(2 / DOF) (chi-square)"""
    v = num(se) * num(se) * num(t)
    return cfmt('%s\t%.4g\t%.2g', name, v, v * sqrt(div(2, num(dof))))


def half_percent_time(se, t=None, dof=49):
    """the production time (t given: t (se / 0.005)^2) or the factor on the time ((se / 0.005)^2)
    that would bring a ratio's standard error SE to 0.5 % (the paper's precision), the error
    scaling as 1 / sqrt(time); its relative error that of a variance from DOF + 1 blocks,
    sqrt(2 / DOF)"""
    a = num(se) / 0.005
    v = a * a if t is None else num(t) * a * a
    return cfmt('%.4g\t%.2g', v, v * sqrt(div(2, num(dof))))


def per_unit_ratio(a, sa, da, b, sb, db):
    """linear response: the response per unit drive at the second drive over the first's,
    (b / db) / (a / da), the drives exact, the responses' relative errors in quadrature (first
    order, independent runs); 1 where the response is linear"""
    a, sa, b, sb, da, db = num(a), num(sa), num(b), num(sb), num(da), num(db)
    x = div(div(b, db), div(a, da))
    return Val(x, abs(x) * sqrt(pw(div(sa, a), 2) + pw(div(sb, b), 2)))


def theory_ratio(v, sv, u, su, th):
    """a force or torque over its theory th, which is linear in the velocity u: the ratio's
    error the value's and u's relative errors in quadrature (num_rel2 of v / th)"""
    return v_rel2(div(num(v), num(th)), v, sv, u, su)


def time_of_steps(steps, dt='0.01'):
    """production time = steps x dt, as awk printed it (%.6g past an integer)"""
    return astr(num(steps) * num(dt))


def production_time(steps, eq, dt=0.01):
    """the summed production time of runs: sum over runs of (steps - equilibration steps) dt, in
    the runs' order, printed as awk prints a number"""
    s = 0.0
    for n in steps:
        s += (num(n) - num(eq)) * dt
    return astr(s)


def rotlet_torque(mu, R, w):
    """Pan et al. 2008 eq. 18: the torque on a sphere of radius R spinning at w in a fluid of
    viscosity mu at rest, T = -8 pi mu w R^3 (Stokes flow)"""
    return cfmt('%.10g', -8 * PI * num(mu) * num(w) * pw(num(R), 3))


def chain_shape_factor(t, st, mu, R, w, n):
    """fig03: the shape factor T_s of a chain of N touching spheres spinning about its axis, its
    torque over N times eq. 18's single-sphere torque, -8 pi mu w N R^3 (T_s = 1 for N = 1)"""
    d = -8 * PI * num(mu) * num(w) * num(n) * pw(num(R), 3)
    return cfmt('%.10g\t%.4g', div(num(t), d), div(num(st), d))


def chain_positions(n, R, c):
    """fig03: the centres of N touching spheres of radius R along x, centred on (c, c, c), as the
    scene's list ([x,y,z],...) at %.4f: x_k = c + (k - (N - 1) / 2) 2 R"""
    n, R, c = int(num(n)), num(R), num(c)
    s = '('
    for k in range(n):
        s += '%s%s' % (',' if k else '', cfmt('[%.4f,%.4f,%.4f]', c + (k - (n - 1) / 2) * 2 * R, c, c))
    return s + ')'


def diff_sigmas(summary, a, b, name):
    """A - B of two summary rows (errors in quadrature, num_diff; the last row of each name) and
    the difference in units of its standard error"""
    va = sa = vb = sb = ''
    for r in rows(summary):
        if fld(r, 1) == a:
            va, sa = fld(r, 2), fld(r, 3)
        if fld(r, 1) == b:
            vb, sb = fld(r, 2), fld(r, 3)
    o = v_diff(va, sa, vb, sb)
    return [o.row(name), cfmt('%s_sigmas\t%.4g\t0', name, div(num(o.v), num(o.se)))]


def drag_theory(mu, R, nf, g, L):
    """fig02: eq. 19's superficial velocity of a fixed sphere dragged by the body force on N_f
    fluid particles, u = N_f g / (6 pi mu R) (Stokes), Hasimoto's (1959) value in a periodic
    cubic array, u (1 - 1.7601 phi^(1/3) + phi - 1.5593 phi^2), and the sphere's volume fraction
    phi = 4 pi R^3 / (3 L^3): "u19 uH phi" """
    m, r, n, g, L = num(mu), num(R), num(nf), num(g), num(L)
    u19 = n * g / (6 * PI * m * r)
    phi = 4 * PI * pw(r, 3) / (3 * pw(L, 3))
    return cfmt('%.10g %.10g %.6g', u19, u19 * (1 - 1.7601 * pw(phi, 1 / 3) + phi - 1.5593 * pw(phi, 2)), phi)


def superficial_velocity(u, su, nf, g, steps):
    """fig02: the fluid's mean velocity u with the larger of the blocks' error and the
    Ornstein-Uhlenbeck error of the total momentum relaxing through the sphere,
    sqrt(2 u / (N_f g T)) over the production time T (friction zeta = N_f g / u, kT = 1):
    "u<TAB>se<TAB>se_blocks<TAB>se_ou" """
    T = num(time_of_steps(steps))
    ou = sqrt(2 * num(u) / (num(nf) * num(g) * T))
    se = su if gt(su, ou) else ou
    return cfmt('%.10g\t%.4g\t%.4g\t%.4g', u, se, su, ou)


def fig02_ratios(summary, u19, uh, q='u_gC3.5'):
    """fig02: the calibrated u over eq. 19's and over Hasimoto's (num_div: the theories exact)"""
    out = []
    for r in rows(summary):
        if fld(r, 1) == q:
            out.append(v_div(fld(r, 2), fld(r, 3), u19).row('u_ratio_eq19_gC3.5'))
            out.append(v_div(fld(r, 2), fld(r, 3), uh).row('u_ratio_hasimoto_gC3.5'))
    return out


def ou_over_blocks(path):
    """fig02: per run, the Ornstein-Uhlenbeck error of u over the blocks' error; its relative
    error that of the blocks' error from 20 blocks, 1 / sqrt(2 x 19), and half of u's relative
    error (the Ornstein-Uhlenbeck error goes as sqrt(u)) in quadrature"""
    out = []
    for r in rows(path)[1:]:
        x = div(num(fld(r, 5)), num(fld(r, 4)))
        out.append(Val(x, x * sqrt(1 / 38 + sq(div(0.5 * num(fld(r, 3)), num(fld(r, 2)))))).row('u_se_ou_over_blocks_gC' + fld(r, 1)))
    return out


def torque_slope(path, omega, gs='5.5'):
    """fig01: the slope of the torque against gamma^C_cf at gamma^S_cf = GS, a weighted (1 / se^2)
    least-squares line (wline), the torques scaled to the paper's Omega = -0.4 by 0.4 / |Omega|
    (Stokes flow is linear in Omega)"""
    w = num(omega)
    f = num(cfmt('%.10g', 0.4 / (-w if w < 0 else w)))
    xs, ys, ss = [], [], []
    for r in rows(path)[1:]:
        if eq(fld(r, 2), num(gs)):
            xs.append(fld(r, 1)); ys.append(num(fld(r, 3)) * f); ss.append(num(fld(r, 4)) * f)
    o = wline(xs, ys, ss)
    return [cfmt('torque_slope_gC\t%.10g\t%.4g', o.slope, o.slope_se)]


def couette_torque(mu, R, c2, w):
    """tab01, Pan et al. 2008 eq. 21: the torque on a sphere spinning at Omega in simple shear of
    vorticity/2 = curl/2, T = 8 pi mu R^3 (curl/2 - Omega)"""
    return cfmt('%.10g', 8 * PI * num(mu) * pw(num(R), 3) * (num(c2) - num(w)))


def cv_pairs(paths):
    """tab01's control variate: per run summary, sphere and component, the run means of the torque
    without its random part (D, torque_on_sK_C) and of the random part (R, torque_random_on_sK_C):
    "D<TAB>R" lines, sorted as text (C locale)"""
    out = []
    for p in paths:
        d, r = {}, {}
        for x in rows(p):
            q = fld(x, 1)
            if re.match(r'^torque_on_s[0-9]_[xyz]$', q):
                d[q[10:]] = fld(x, 2)
            if re.match(r'^torque_random_on_s[0-9]_[xyz]$', q):
                r[q[17:]] = fld(x, 2)
        out.extend(d[k] + '\t' + r.get(k, '') for k in d)
    return sorted(out, key=lambda l: l.encode())


def control_variate(path, t='10'):
    """tab01: the control variate R (zero mean) of the torque D from n "D<TAB>R" pairs of run
    means: sample variances and covariance (one pass, n - 1), the intensities (variance x the
    runs' time t) of D, R and D + R, the correlation rho, the best coefficient c = -cov / var R
    and its variance factor 1 - rho^2 (Rubinstein & Marcus 1985); stderrs: a variance's
    sqrt(2 / (n - 1)), rho's (1 - rho^2) / sqrt(n - 3) (Fisher)"""
    t = num(t)
    n = 0
    d = r = dd = rr = dr = 0.0
    for x in rows(path):
        a, b = num(fld(x, 1)), num(fld(x, 2))
        n += 1; d += a; r += b; dd += a * a; rr += b * b; dr += a * b
    md = d / n; mr = r / n
    vd = (dd - n * md * md) / (n - 1); vr = (rr - n * mr * mr) / (n - 1)
    c = (dr - n * md * mr) / (n - 1); vt = vd + vr + 2 * c
    rho = c / sqrt(vd * vr); f = sqrt(2 / (n - 1))
    q = lambda name, v, se: cfmt('%s\t%.6g\t%.3g', name, v, se)
    return [q('cv_samples', n, 0),
            q('cv_torque_mean', md, sqrt(vd / n)), q('cv_random_mean', mr, sqrt(vr / n)),
            q('cv_noise_D', vd * t, vd * t * f), q('cv_noise_R', vr * t, vr * t * f), q('cv_noise_total', vt * t, vt * t * f),
            q('cv_rho', rho, (1 - rho * rho) / sqrt(n - 3)), q('cv_c_best', div(-c, vr), sqrt((1 - rho * rho) * vd / vr / (n - 3))),
            q('cv_variance_factor_best', 1 - rho * rho, 2 * abs(rho) * (1 - rho * rho) / sqrt(n - 3))]


def bin_window(z, half):
    """the range z - half : z + half (%g), a block_mean's bins"""
    return cfmt('%g:%g', num(z) - num(half), num(z) + num(half))


def linear_scale(v, sv, g, g0):
    """a response measured at drive g0 scaled to drive g (linear response): (v g) / g0, its
    error likewise"""
    o = v_scale(v, sv, g)
    return v_div(o.v, o.se, g0)


def wall_sphere_theory(uh, mu, R, h):
    """tab02, Pan et al. 2008 eq. 22: drag and torque on a sphere at distance h from a wall in a
    shear flow of velocity u_h at its centre (Goldman, Cox & Brenner 1967, as the paper fits
    them): F = 6 pi mu u R (1 - q^2 / 9) / (1 - 0.6526 q + 0.3160 q^3 - 0.242 q^4),
    T = 8/3 pi mu u R^3 / h (1 + 0.0758 q + 0.049 q^2), q = R / h: "F T" """
    u, m, R, h = num(uh), num(mu), num(R), num(h)
    q = R / h
    F = 6 * PI * m * u * R * (1 - pw(q, 2) / 9) / (1 - 0.6526 * q + 0.3160 * pw(q, 3) - 0.242 * pw(q, 4))
    T = 8 / 3 * PI * m * u * pw(R, 3) / h * (1 + 0.0758 * q + 0.049 * pw(q, 2))
    return cfmt('%.10g %.10g', F, T)


def tab02_row(r, uh, suh, F, sF, T, sT, Fth, Tth, pF, pT):
    """tab02: a row of the rendered Table 2 (formatting; the paper's Re per row)"""
    re_ = '0.0491' if eq(r, 1) else '0.0993' if eq(r, 2) else '0.201'
    return cfmt('%s\t%s\t%.4f +- %.4f\t%s\t%.3f +- %.3f\t%.3f\tdrag_ratio_row%s\t%s\t%.4f +- %.4f\t%.4f\ttorque_ratio_row%s',
                r, re_, uh, suh, pF, F, sF, Fth, r, pT, T, sT, Tth, r)


def no_slip_poiseuille(g, z, mu):
    """tab02: the no-slip Poiseuille velocity at height z of a channel with walls at z = 1 and 9
    (rho = 3): u = 3 g (z - 1) (9 - z) / (2 mu)"""
    g, z, m = num(g), num(z), num(mu)
    return cfmt('%.10g', g * 3 * (z - 1) * (9 - z) / (2 * m))


def two_sphere_theory(l, u, mu, R):
    """tab03, Pan et al. 2008 eq. 23: drag and torque on each of two spheres a distance l apart,
    flow u normal to their line of centres (the method of reflections to q^5, q = R / l):
    F = 6 pi mu R u (1 - 3q/4 + 9q^2/16 - 59q^3/64 + 465q^4/256 - 15813q^5/7168),
    T = 8 pi mu R^3 u / l (3q/4 - 9q^2/16 + 27q^3/64 - 273q^4/256 + 1683q^5/1024): "F T" """
    l, u, m, R = num(l), num(u), num(mu), num(R)
    q = R / l
    F = 6 * PI * m * R * u * (1 - 3 * q / 4 + 9 * pw(q, 2) / 16 - 59 * pw(q, 3) / 64 + 465 * pw(q, 4) / 256 - 15813 * pw(q, 5) / 7168)
    T = 8 * PI * m * pw(R, 3) * u / l * (3 * q / 4 - 9 * pw(q, 2) / 16 + 27 * pw(q, 3) / 64 - 273 * pw(q, 4) / 256 + 1683 * pw(q, 5) / 1024)
    return cfmt('%.10g %.10g', F, T)


def two_sphere_positions(L, l):
    """tab03: the box centre c = L / 2 and the spheres' y = c -+ l / 2 (%.4f each): "c ya yb" """
    c = cfmt('%.4f', num(L) / 2)
    return '%s %s %s' % (c, cfmt('%.4f', num(c) - num(l) / 2), cfmt('%.4f', num(c) + num(l) / 2))


def tab03_row(r, l, u, F, sF, T, sT, Fth, Tth, pF, pT):
    """tab03: a row of the rendered Table 3 (formatting)"""
    return cfmt('%s\t%.2f\t%s\t%.3f +- %.3f\t%.3f\tdrag_ratio_row%s\t%s\t%.4f +- %.4f\t%.4f\ttorque_ratio_row%s',
                l, u, pF, F, sF, Fth, r, pT, T, sT, Tth, r)


def linear_decision(v, se):
    """tab03's rule for the projection's drive (fixed before the ladder ran): 1 if the torque
    per unit u is linear, |x - 1| <= 0.10 + 2 se, and resolved, 2 se <= 0.20; else 0"""
    d = abs(num(v) - 1)
    return '1' if le(d, 0.10 + 2 * num(se)) and le(2 * num(se), 0.20) else '0'


def torque_projection(r, u, u0, noise, snoise, tth, cpu, steps):
    """tab03: the time for a torque stderr of 10 % of eq. 23's torque at drive u,
    t = noise / (0.1 T(u))^2 with T(u) = T(u0) u / u0 (linear), and its CPU-hours at the row's
    cost per time unit (cpu / (steps dt)); the hours left after the 600 time units run at u0
    (worth 600 (u0 / u)^2 at u); the hours at u0 itself; stderrs the noise's"""
    n, sn, th, c_, st = num(noise), num(snoise), num(tth), num(cpu), num(steps)
    T = th * num(u) / num(u0)
    t = n / pw(0.1 * T, 2)
    c = c_ / (st * 0.01)
    f = div(sn, n)
    h = t * c / 3600
    rem = (t - 600 * pw(num(u0) / num(u), 2)) * c / 3600
    t3 = n / pw(0.1 * th, 2)
    return ['projection_u_row%s\t%s\t0' % (r, u),
            cfmt('projection_time_row%s\t%.4g\t%.2g', r, t, t * f),
            cfmt('projection_cpu_hours_row%s\t%.4g\t%.2g', r, h, h * f),
            cfmt('projection_cpu_hours_remaining_row%s\t%.4g\t%.2g', r, rem, rem * f),
            cfmt('projection_cpu_hours_u0.3_row%s\t%.4g\t%.2g', r, t3 * c / 3600, t3 * c / 3600 * f)]


def sphere_blocks(lines, nb):
    """two fixed spheres a and b: per sample the drag per sphere (F_a + F_b) / 2 and the torque
    (T_a - T_b) / 2 ("Fa Fb Ta Tb" lines), then their means over NB contiguous blocks, the first
    n mod NB samples skipped (as src/core/blockavg.c): "block drag torque" rows (the two
    spheres' noises averaged sample by sample, so their correlation is in the blocks' scatter)"""
    nb = int(num(nb))
    F, T = [], []
    for l in lines:
        a = l.split('\t')
        F.append((float(a[0]) + float(a[1])) / 2)
        T.append((float(a[2]) - float(a[3])) / 2)
    n = len(F)
    ln = n // nb
    skip = n - ln * nb
    out = ['block\tdrag\ttorque']
    for b in range(nb):
        f = F[skip + b * ln: skip + (b + 1) * ln]
        t = T[skip + b * ln: skip + (b + 1) * ln]
        out.append(cfmt('%d\t%.10g\t%.10g', b, _fmean(f), _fmean(t)))
    return out


def window_means(xs, w):
    """the means of W consecutive samples from the first, a last partial window dropped (pan-estimators:
    the twins' series kept at the resolution their analysis needs, W = 5 steps)"""
    return [cfmt('%.10g', _fmean(xs[b * w:(b + 1) * w])) for b in range(len(xs) // w)]


def _fmean(xs):
    """mean (num_mean) of numbers, summed in order: nan if any is NaN or there are none"""
    if not xs:
        return 'nan'
    s = 0.0
    for x in xs:
        if math.isnan(x):
            return 'nan'
        s += x
    return s / len(xs)


def colloid_count(L, density='0.027'):
    """eq16: the colloids of a box of side L at the number density of the 10^3 box (rounded)"""
    return cfmt('%d', num(density) * pw(num(L), 3) + 0.5)


def stokes_radius(D, sD, mu):
    """Pan et al. 2008 eq. 16 with c = 6 (Stokes-Einstein, kT = 1): R = 1 / (6 pi mu D), the
    error from D's alone (mu the paper's, exact)"""
    return v_rel1(div(1, 6 * PI * num(mu) * num(D)), D, sD)


def box_corrected(D, sD, mu, L):
    """eq16: D corrected for the periodic box, D + 2.837297 kT / (6 pi mu L) (Yeh & Hummer 2004,
    cubic box; the correction exact), and eq. 16's R from it"""
    c = 2.837297 / (6 * PI * num(mu) * num(L))
    d = num(D) + c
    return [cfmt('D_colloid_box_corrected\t%.10g\t%.4g', d, sD), stokes_radius(d, sD, mu).row('R_box_corrected')]


def se_ratio_row(q, pair, g, n):
    """eq16: the replicas' error of D over the colloid groups' pooled error G, and its relative
    error that of a standard deviation from N replicas, 1 / sqrt(2 (N - 1))"""
    s = num(parse_pair(pair).se)
    x = div(s, num(g))
    return cfmt('%s\t%.4g\t%.2g', q, x, div(x, sqrt(2 * (num(n) - 1))))


def finite_size_fit(path):
    """eq16: D(L) = D_inf + slope / L, a weighted least-squares line in 1/L (wline) over the rows
    of d-of-L.tsv with a usable error; the errors scaled by sqrt(chi^2 / dof) when that exceeds 1
    (the scatter exceeding the errors); r2 the unweighted coefficient of determination: the table
    fit-d-of-L.tsv (None: fewer than 3 usable rows)"""
    xs, ys, ss = [], [], []
    for r in rows(path)[1:]:
        if usable(fld(r, 4), fld(r, 5)):
            xs.append(fld(r, 2)); ys.append(fld(r, 4)); ss.append(fld(r, 5))
    n = len(xs)
    if n < 3:
        return None
    o = wline(xs, ys, ss)
    b, a = num(o.slope), num(o.icpt)
    chi2 = ssr = ym = sst = 0.0
    for x, y, s in zip(xs, ys, ss):
        rr = num(y) - (a + b * num(x))
        chi2 += sq(div(rr, num(s))); ssr += sq(rr); ym += num(y) / n
    for y in ys:
        sst += sq(num(y) - ym)
    c = chi2 / (n - 2)
    f = sqrt(c if c > 1 else 1)
    return ['quantity\tvalue\tstderr',
            cfmt('slope\t%.10g\t%.4g', b, f * num(o.slope_se)),
            cfmt('value_at_centre\t%.10g\t%.4g', a, f * num(o.icpt_se)),
            cfmt('r2\t%.10g\t0', 1 - ssr / sst if sst > 0 else 1), cfmt('chi2_dof\t%.10g\t0', c), cfmt('points\t%d\t0', n)]


def yeh_hummer_rows(eta, slope, dinf, mu):
    """eq16: Yeh & Hummer's (2004) coefficient of the finite-size term, c = 2.837297 kT /
    (6 pi eta) with the measured eta (its relative error), the fitted slope's magnitude over it,
    eq. 16's R from the extrapolated D with the paper's mu (D's error) and with the measured eta
    (both errors in quadrature), and eta itself"""
    E, S, DI = parse_pair(eta), parse_pair(slope), parse_pair(dinf)
    m = num(mu)
    cy = v_rel1(2.837297 / (6 * PI * num(E.v)), E.v, E.se)
    return [cy.row('yeh_hummer_coefficient'),
            v_ratio(-num(S.v), S.se, cy.v, cy.se).row('finite_size_slope_over_yeh_hummer'),
            stokes_radius(DI.v, DI.se, m).row('R_extrapolated'),
            v_rel2(div(1, 6 * PI * num(E.v) * num(DI.v)), DI.v, DI.se, E.v, E.se).row('R_extrapolated_measured_eta'),
            Val(E.v, E.se).row('measured_eta')]


def yeh_hummer_corrections(summary, cyh, boxes):
    """eq16: the difference D(8) - D(6) that Yeh & Hummer's c expects, c (1/6 - 1/8), and each
    box's D corrected by c / L (errors of D and c in quadrature: c comes from the fluid's
    viscosity, independent of the boxes' runs)"""
    C = parse_pair(cyh)
    out = [v_scale(C.v, C.se, 1 / 6 - 1 / 8).row('yeh_hummer_D_L8_minus_L6')]
    for L in boxes:
        d = parse_pair(_lookup(summary, 'D_colloid_L' + L))
        out.append(v_lin2(1, d.v, d.se, 1 / num(L), C.v, C.se).row('D_colloid_L%s_yeh_hummer_corrected' % L))
    return out


def _pan_cmd_fit(a):
    t = finite_size_fit(a[0])
    if t is None:
        sys.stderr.write('eq16: fewer than 3 usable rows in %s\n' % a[0])
        return 1
    return t


def _stdin_lines():
    return [l for l in sys.stdin.read().split('\n') if l != '']


PAN_COMMANDS = {
    # table-rows FILE [SUFFIX]: the rows after the header (SUFFIX: the name suffixed, 3 columns)
    'table-rows': lambda a: table_rows(a[0], a[1] if len(a) > 1 else ''),
    # mean-runs < "v<TAB>se" lines -> the equal-weight mean of runs
    'mean-runs': lambda a: [mean_runs(_stdin_lines()).pair()],
    # mean-se < values (first column) -> mean and standard error of independent values
    'mean-se': lambda a: [mean_se([l.split('\t')[0] for l in _stdin_lines()]).pair()],
    # column-mean FILE COL -> mean and standard error of a column after the header
    'column-mean': lambda a: [column_mean_se(a[0], int(a[1])).pair()],
    # div "v<TAB>se" C [NAME] -> (v +- se) / c, as a pair or a row NAME
    'div': lambda a: [(lambda o: o.row(a[2]) if len(a) > 2 else o.pair())(v_div(parse_pair(a[0]).v, parse_pair(a[0]).se, a[1]))],
    # noise-row NAME SE TIME DOF
    'noise-row': lambda a: [noise_row(*a[:4])],
    # half-percent-time SE [TIME] DOF (TIME "-": the factor on the time)
    'half-percent-time': lambda a: [half_percent_time(a[0], None if a[1] == '-' else a[1], a[2])],
    # per-unit-ratio "a<TAB>se" DRIVE_A "b<TAB>se" DRIVE_B [NAME]
    'per-unit-ratio': lambda a: [(lambda o: o.row(a[4]) if len(a) > 4 else o.pair())(
        per_unit_ratio(parse_pair(a[0]).v, parse_pair(a[0]).se, a[1], parse_pair(a[2]).v, parse_pair(a[2]).se, a[3]))],
    # theory-ratio NAME "v<TAB>se" "u<TAB>se" THEORY
    # per-drive-ratio "Ta<TAB>se" "curl2a<TAB>se" OMEGA_A "Tb<TAB>se" "curl2b<TAB>se" OMEGA_B NAME: tab01's torque per
    # unit drive curl/2 - Omega (the measured curl/2, its error neglected: 0.1-0.2 %)
    'per-drive-ratio': lambda a: [per_unit_ratio(parse_pair(a[0]).v, parse_pair(a[0]).se, num(parse_pair(a[1]).v) - num(a[2]),
                                                 parse_pair(a[3]).v, parse_pair(a[3]).se, num(parse_pair(a[4]).v) - num(a[5])).row(a[6])],
    'theory-ratio': lambda a: [theory_ratio(parse_pair(a[1]).v, parse_pair(a[1]).se, parse_pair(a[2]).v, parse_pair(a[2]).se, a[3]).row(a[0])],
    'time-of-steps': lambda a: [time_of_steps(a[0])],
    # production-time EQ_STEPS < steps lines (first column)
    'production-time': lambda a: [production_time([l.split('\t')[0] for l in _stdin_lines()], a[0])],
    'rotlet-torque': lambda a: [rotlet_torque(*a[:3])],
    'chain-shape-factor': lambda a: [chain_shape_factor(parse_pair(a[0]).v, parse_pair(a[0]).se, *a[1:5])],
    'chain-positions': lambda a: [chain_positions(*a[:3])],
    'diff-sigmas': lambda a: diff_sigmas(*a[:4]),
    'drag-theory': lambda a: [drag_theory(*a[:5])],
    'superficial-velocity': lambda a: [superficial_velocity(parse_pair(a[0]).v, parse_pair(a[0]).se, *a[1:4])],
    'fig02-ratios': lambda a: fig02_ratios(a[0], a[1], a[2]),
    'ou-over-blocks': lambda a: ou_over_blocks(a[0]),
    'torque-slope': lambda a: torque_slope(a[0], a[1]),
    'couette-torque': lambda a: [couette_torque(*a[:4])],
    'cv-pairs': lambda a: cv_pairs(a),
    'control-variate': lambda a: control_variate(a[0]),
    'bin-window': lambda a: [bin_window(a[0], a[1])],
    'linear-scale': lambda a: [linear_scale(parse_pair(a[0]).v, parse_pair(a[0]).se, a[1], a[2]).pair()],
    'wall-sphere-theory': lambda a: [wall_sphere_theory(*a[:4])],
    # tab02-row R "uh" "F" "T" FTH TTH PAPER_F PAPER_T (pairs "v<TAB>se")
    'tab02-row': lambda a: [tab02_row(a[0], *_pairs(a[1:4]), *a[4:8])],
    'no-slip-poiseuille': lambda a: [no_slip_poiseuille(*a[:3])],
    'two-sphere-theory': lambda a: [two_sphere_theory(*a[:4])],
    # fluid-count L -> 3 L^3 (%d): the fluid particles of a box of side L at density 3
    'fluid-count': lambda a: [cfmt('%d', 3 * pw(num(a[0]), 3))],
    # box-centre L DIGITS -> L / 2 to DIGITS decimals
    'box-centre': lambda a: [cfmt('%.*f', a[1], num(a[0]) / 2)],
    # window-means W < samples -> the mean of each W consecutive samples (%.10g), a last partial window dropped
    'window-means': lambda a: window_means([float(l) for l in _stdin_lines()], int(num(a[0]))),
    'two-sphere-positions': lambda a: [two_sphere_positions(a[0], a[1])],
    # tab03-row R L "u" "F" "T" FTH TTH PAPER_F PAPER_T
    'tab03-row': lambda a: [tab03_row(a[0], a[1], parse_pair(a[2]).v, parse_pair(a[3]).v, parse_pair(a[3]).se,
                                      parse_pair(a[4]).v, parse_pair(a[4]).se, *a[5:9])],
    'linear-decision': lambda a: [linear_decision(parse_pair(a[0]).v, parse_pair(a[0]).se)],
    # torque-projection R U U0 "noise" THEORY "cpu" "steps"
    'torque-projection': lambda a: torque_projection(a[0], a[1], a[2], parse_pair(a[3]).v, parse_pair(a[3]).se, a[4],
                                                     parse_pair(a[5]).v, parse_pair(a[6]).v),
    # sum-first FMT < lines: FMT of the sum of their first column, in order
    'sum-first': lambda a: [cfmt(a[0], _sum_first(_stdin_lines()))],
    # sphere-blocks BLOCKS < "Fa Fb Ta Tb" lines
    'sphere-blocks': lambda a: sphere_blocks(_stdin_lines(), a[0]),
    'colloid-count': lambda a: [colloid_count(a[0])],
    # stokes-radius NAME "D<TAB>se" MU
    'stokes-radius': lambda a: [stokes_radius(parse_pair(a[1]).v, parse_pair(a[1]).se, a[2]).row(a[0])],
    'box-corrected': lambda a: box_corrected(parse_pair(a[0]).v, parse_pair(a[0]).se, a[1], a[2]),
    'se-ratio-row': lambda a: [se_ratio_row(*a[:4])],
    # inverse X -> 1 / x (%.10g)
    'inverse': lambda a: [cfmt('%.10g', div(1, num(a[0])))],
    'finite-size-fit': _pan_cmd_fit,
    'yeh-hummer-rows': lambda a: yeh_hummer_rows(*a[:4]),
    # yeh-hummer-corrections SUMMARY "c<TAB>se" "L..."
    'yeh-hummer-corrections': lambda a: yeh_hummer_corrections(a[0], a[1], a[2].split()),
}


def _pairs(ps, parse=None):
    """the value and error of each "v<TAB>se" (or of whatever PARSE reads), in one list"""
    out = []
    for p in ps:
        o = (parse or parse_pair)(p)
        out += [o.v, o.se]
    return out


def _sum_first(lines):
    s = 0.0
    for l in lines:
        s += num(l.split('\t')[0])
    return s


# ---------------------------------------------------------------- methods/pan-estimators

def precision_totals(path):
    """pan-estimators: the CPU-hours every claim needs for its deciding stderr, summed over the
    claims (precision.tsv's columns 13 and 14: at the paper's values and at ours; inf left out)"""
    p = o = 0.0
    for r in rows(path)[1:]:
        if fld(r, 13) != 'inf':
            p += num(fld(r, 13))
        if fld(r, 14) != 'inf':
            o += num(fld(r, 14))
    return [cfmt('precision_cpu_hours_at_paper_values\t%.4g\t0', p), cfmt('precision_cpu_hours_at_our_values\t%.4g\t0', o)]


def half_percent_totals(path):
    """pan-estimators: the CPU-hours for a stderr of 0.5 % of every number Pan prints (column 13),
    summed per source (the experiment's name up to its first '-', in the order first met) and in all"""
    order, h, tot = [], {}, 0.0
    for r in rows(path)[1:]:
        k = re.sub(r'-.*', '', re.sub(r'.*/', '', fld(r, 1), count=1), count=1)
        if k not in h:
            h[k] = 0.0
            order.append(k)
        h[k] += num(fld(r, 13))
        tot += num(fld(r, 13))
    return [cfmt('half_percent_cpu_hours_%s\t%.4g\t0', k, h[k]) for k in order] + [cfmt('half_percent_cpu_hours_all\t%.4g\t0', tot)]


def ladder_row(w, t, st, prod, cpu, mu, R):
    """pan-estimators' rotation ladder: at spin Omega, the torque over eq. 18 (-8 pi mu Omega R^3),
    the noise (stderr^2 x production time) and the figure of merit (se / T)^2 x CPU-hours: a
    ladder.tsv row"""
    T, sT, m, r = num(t), num(st), num(mu), num(R)
    t18 = -8 * PI * m * num(w) * r * r * r
    return cfmt('%s\t%s\t%s\t%.10g\t%.4g\t%.4g\t%.4g\t%.4g', w, t, st, T / t18, sT / t18, sT * sT * num(prod), cpu, sq(sT / T) * num(cpu))


def _row_where(path, conds):
    """the first row after the header whose columns equal the given values (mawk's comparison)"""
    for r in rows(path)[1:]:
        if all(eq(fld(r, c), v) for c, v in conds):
            return r
    return None


def ladder_rows(path, w):
    """pan-estimators: a drive's torque ratio to eq. 18 and its noise, whose stderr is that of a
    variance from 50 blocks, sqrt(2 / 49)"""
    r = _row_where(path, [(1, w)])
    return ['ladder_torque_ratio_W%s\t%s\t%s' % (w, fld(r, 4), fld(r, 5)),
            'ladder_noise_W%s\t%s\t%s' % (w, fld(r, 6), astr(num(fld(r, 6)) * sqrt(2 / 49)))]


def hold_row(L, u, drag, sdrag, force, sforce, prod, cpu, mu, R, fext):
    """pan-estimators' held mean velocity: the drag coefficient zeta = drag / u, over Stokes
    6 pi mu R and over Hasimoto's simple cubic array K(phi) = 1 / (1 - 1.7601 phi^(1/3) + phi
    - 1.5593 phi^2) (Sangani & Acrivos 1982), phi = (4/3) pi R^3 / L^3; u at fig02's F_ext from
    zeta, Hasimoto's u there; the noise of the drag and of the total force (variance x time) and
    the Einstein form of the total force's fluctuations, var x T / (2 kT): a hold.tsv row"""
    m, r, Lf, uf, Fe = num(mu), num(R), num(L), num(u), num(fext)
    z, zs = num(drag) / uf, num(sdrag) / uf
    S = 6 * PI * m * r
    phi = 4 / 3 * PI * r * r * r / (Lf * Lf * Lf)
    K = 1 / (1 - 1.7601 * pw(phi, 1 / 3) + phi - 1.5593 * phi * phi)
    sd, sf, T = num(sdrag), num(sforce), num(prod)
    return cfmt('%s\t%s\t%.10g\t%.4g\t%.10g\t%.4g\t%.10g\t%.10g\t%.4g\t%.10g\t%.4g\t%.10g\t%.4g\t%.4g\t%.4g\t%.4g',
                L, u, z, zs, z / S, zs / S, K, z / S / K, zs / S / K, Fe / z, Fe / z * zs / z, Fe / (S * K),
                sd * sd * T, sf * sf * T, sf * sf * T / 2, cpu)


def hold_rows(path, L, u):
    """pan-estimators: the summary rows of a held-u run (K over Hasimoto's, u at F_ext, zeta)"""
    r = _row_where(path, [(1, L), (2, u)])
    return ['K_over_hasimoto_L%s_u%s\t%s\t%s' % (L, u, fld(r, 8), fld(r, 9)),
            'u_at_fext_L%s_u%s\t%s\t%s' % (L, u, fld(r, 10), fld(r, 11)),
            'zeta_L%s_u%s\t%s\t%s' % (L, u, fld(r, 3), fld(r, 4))]


def hold_ratio(path, L1, u1, L2, u2, name, hname=None):
    """pan-estimators: zeta of one held-u run over another's (relative errors in quadrature), and
    Hasimoto's K of the two boxes over each other (exact)"""
    a, b = _row_where(path, [(1, L1), (2, u1)]), _row_where(path, [(1, L2), (2, u2)])
    out = [v_ratio(fld(a, 3), fld(a, 4), fld(b, 3), fld(b, 4)).row(name)]
    if hname:
        out.append(cfmt('%s\t%.10g\t0', hname, num(fld(a, 7)) / num(fld(b, 7))))
    return out


def prod_time(steps, args, scene):
    """the production time units (dt = 0.01) of a run: its steps less the equilibration of its
    arguments (a line equilibration=N of .args), else of its scene (the last `equilibration =`
    setting outside comments), else 0"""
    eq = 0.0
    with open(scene) as f:
        for l in f.read().split('\n'):
            l = re.sub(r'#.*', '', l, count=1)
            if re.match(r'^[ \t]*equilibration[ \t]*=', l):
                eq = num(re.sub(r'.*=[ \t]*', '', l, count=1))
    with open(args) as f:
        for l in f.read().split('\n'):
            if l.startswith('equilibration='):
                eq = num(l.split('=', 1)[1])
    return cfmt('%.6g', (num(steps) - eq) * 0.01)


def gk_rotational_friction(noise, snoise, mu, R):
    """pan-estimators: the rotational friction by the Einstein form of Green-Kubo, the total
    torque's variance x time / (2 kT), over eq. 18's 8 pi mu R^3"""
    z = 8 * PI * num(mu) * num(R) * num(R) * num(R)
    return v_div(num(noise) / 2, num(snoise) / 2, z)


def twins(kind, files, steady, plain, out):
    """pan-estimators' twins (correlated sampling): per seed a base run, a driven one and a tiny-drive
    one branched from the same state, their series as means over windows of 5 steps (W = 0.05 time
    units; FILES: base, drive, tiny per seed). Per bin of 5 windows: the response (driven minus base,
    its stderr from the seeds' scatter), over the steady value STEADY, and the rms of the tiny twin's
    difference and of the driven twin's difference about the response, each over sqrt(2) x the rms
    of one run's window means over the second half (1: independent, 0: identical) - written to OUT;
    the Lyapunov rate, the slope of log(tiny decorrelation) against time where it lies in
    (0.005, 0.3) (line); the decorrelation time, the first bin start where it reaches 0.5 (stderr:
    the bin, 0.25); per window [t1, t2] after the branch, the twin estimator's (the mean difference
    there, over the seeds) bias against STEADY and its variance x 2 t2 (a driven and a base run)
    over the plain average's variance x time PLAIN, with a variance's relative error
    sqrt(2 / (n - 1)): the summary rows"""
    W = 0.05
    ns = len(files) // 3
    x = {}
    nw = 0
    for si in range(ns):
        for k in range(3):
            with open(files[3 * si + k]) as f:
                vals = f.read().split('\n')
            if vals and vals[-1] == '':
                vals.pop()
            x[si, k] = vals
            nw = len(vals)

    def xv(si, k, w):
        v = x[si, k]
        return num(v[w - 1]) if w - 1 < len(v) else 0.0
    v = [x[si, 0][w - 1] if w - 1 < len(x[si, 0]) else '' for si in range(ns) for w in range(1, nw + 1) if 2 * w > nw]
    o = mean_se(v)
    ind = sqrt(2) * (num(o.se) * sqrt(len(v)))
    table = ['t\tresponse\tresponse_se\tresponse_over_steady\ttiny_decorrelation\tfull_decorrelation']
    nb = nw // 5
    tdec = 'nan'
    lx, ly = [], []
    for b in range(1, nb + 1):
        e2 = r2 = 0.0
        rr = []
        for si in range(ns):
            rs = 0.0
            for w in range(5 * (b - 1) + 1, 5 * b + 1):
                e2 += sq(xv(si, 2, w) - xv(si, 0, w))
                rs += xv(si, 1, w) - xv(si, 0, w)
            rr.append(rs / 5)
        o = mean_se(rr)
        resp, rse = o.v, o.se
        for si in range(ns):
            for w in range(5 * (b - 1) + 1, 5 * b + 1):
                r2 += sq(xv(si, 1, w) - xv(si, 0, w) - num(resp))
        c = div(sqrt(e2 / (5 * ns)), ind)
        cf = div(sqrt(r2 / (5 * ns)), ind)
        t = (b - 0.5) * 5 * W
        if tdec == 'nan' and ge(c, 0.5):
            tdec = (b - 1) * 5 * W
        if gt(c, 0.005) and lt(c, 0.3):
            lx.append(t)
            ly.append(log(c))
        table.append(cfmt('%.3f\t%.6g\t%.4g\t%.4g\t%.4g\t%.4g', t, resp, rse, 'nan' if steady == '' else div(num(resp), num(steady)), c, cf))
    with open(out, 'w') as f:
        f.write(''.join(l + '\n' for l in table))
    ln = line(lx, ly)
    rows_ = ['twin_%s_lyapunov_rate\t%s\t%s' % (kind, fmt_nan('%.4g', ln.slope), fmt_nan('%.2g', ln.slope_se)),
             cfmt('twin_%s_decorrelation_time\t%s\t%.2g', kind, tdec, 5 * W)]
    for t1, t2 in (('0.25', '0.5'), ('0.5', '1'), ('1', '2'), ('2', '4')):
        y = []
        for si in range(ns):
            a = 0.0
            k = 0
            for w in range(1, nw + 1):
                if (w - 1) * W >= num(t1) and w * W <= num(t2) + 1e-9:
                    a += xv(si, 1, w) - xv(si, 0, w)
                    k += 1
            y.append(div(a, k))
        o = mean_se(y)
        S, P = steady, plain
        bias = 'nan' if S == '' else num(o.v) / num(S) - 1
        bse = 'nan' if S == '' else num(o.se) / abs(num(S))
        vr = 'nan' if P == '' else num(o.se) * num(o.se) * ns * 2 * num(t2) / num(P)
        vrs = 'nan' if P == '' else num(o.se) * num(o.se) * ns * 2 * num(t2) / num(P) * sqrt(2 / (ns - 1))
        rows_.append('twin_%s_bias_%s_%s\t%s\t%s' % (kind, t1, t2, fmt_nan('%.4g', bias), fmt_nan('%.2g', bse)))
        rows_.append('twin_%s_variance_ratio_%s_%s\t%s\t%s' % (kind, t1, t2, fmt_nan('%.4g', vr), fmt_nan('%.2g', vrs)))
    return rows_


def pair_periodic_factor(L, R):
    """the leading periodic-array correction of the drag on each of two spheres per cubic cell of side
    L: 1 / (1 - 2 x 2.837297 R / L) (the partner's images and the sphere's own each give the backflow
    -2.837297 F / (6 pi mu L) at the sphere: the Hasimoto / Yeh-Hummer constant), %.10g"""
    return cfmt('%.10g', 1 / (1 - 2 * 2.837297 * num(R) / num(L)))


def pair_box_row(L, l, u, drag, sdrag, F, P, pF):
    """pan-estimators: a pair's drag per sphere over eq. 23's F, over the periodic prediction P as
    well, and Pan's value pF over F: a pair_boxes.tsv row"""
    d, sd_, F_, P_ = num(drag), num(sdrag), num(F), num(P)
    return cfmt('%s\t%s\t%s\t%s\t%s\t%.10g\t%.4g\t%.10g\t%.10g\t%.4g\t%.10g', L, l, u, drag, sdrag, d / F_, sd_ / F_, P_,
                d / F_ / P_, sd_ / F_ / P_, num(pF) / F_)


def cols_where(path, conds, cols):
    """selection: the given columns of the first row after the header whose columns equal the given
    values ("C=V" each, mawk's comparison), tab-separated; None if there is none"""
    r = _row_where(path, [(int(c.split('=', 1)[0]), c.split('=', 1)[1]) for c in conds])
    return None if r is None else '\t'.join(fld(r, int(c)) for c in cols)


def torque_over_drag(files):
    """pan-estimators: the torque over the drag of a pair of spheres from the per-block tables of one
    or more runs: each run's block means (mean_se of the columns drag and torque, as printed), the
    runs' inverse-variance weighted means (wmean_se), their ratio (first order):
    "T/F<TAB>se<TAB>F<TAB>F_se<TAB>T<TAB>T_se" """
    F = [column_mean_se(f, 2).pair() for f in files]
    T = [column_mean_se(f, 3).pair() for f in files]
    oF = wmean_se([x.split('\t')[0] for x in F], [x.split('\t')[1] for x in F])
    oT = wmean_se([x.split('\t')[0] for x in T], [x.split('\t')[1] for x in T])
    return '\t'.join([v_ratio(oT.v, oT.se, oF.v, oF.se).pair(), oF.pair(), oT.pair()])


def tf_ratios(tf8, tf12, p8, p12):
    """pan-estimators: T/F and the drag of the 8^3 box over the 12^3 box's (first order), and the
    periodic prediction's ratio of the drags"""
    a, b = tf8.split('\t'), tf12.split('\t')
    return [v_ratio(a[0], a[1], b[0], b[1]).row('tf_L8_over_L12'), v_ratio(a[2], a[3], b[2], b[3]).row('drag_L8_over_L12'),
            cfmt('drag_periodic_L8_over_L12\t%.10g\t0', num(p8) / num(p12))]


def tf_torque(tf12, drag, t23):
    """pan-estimators: Table 3's row-3 torque as (T/F of the 12^3 box) x the 30^3 drag (relative
    errors in quadrature), and over eq. 23's torque"""
    a, d = tf12.split('\t'), parse_pair(drag)
    o = v_product(a[0], a[1], d.v, d.se)
    return [o.row('tab03_row3_torque_via_tf'), v_div(o.v, o.se, t23).row('tab03_row3_torque_ratio_via_tf')]


def pan_compare_row(lab, q, p, pt, v, se, r, rse):
    """pan-estimators: one of Pan's simulated numbers p beside ours (v +- se): their ratio, the
    difference in our stderrs, Pan's over his theory pt ("-": none) and ours over ours (r +- rse)"""
    V, S, P = num(v), num(se), num(p)
    return cfmt('%s\t%s\t%s\t%.10g\t%.4g\t%.10g\t%.4g\t%.3g\t%s\t%s\t%s', lab, q, p, v, se, div(V, P), div(S, P), div(V - P, S),
                '-' if pt == '-' else cfmt('%.10g', div(P, num(pt))), r, rse)


def est_row(q, e, st, v, se, c, ck, k):
    """pan-estimators' figure of merit of an estimator: the relative variance x CPU-hours,
    r = (se / value)^2 x CPU_h, and r / 1e-4, the CPU-hours a relative stderr of 1 % needs: an
    estimators.tsv row"""
    r = pw(div(num(se), num(v)), 2) * num(c)
    if r < 0:
        r = -r
    return cfmt('%s\t%s\t%s\t%.6g\t%.4g\t%.4g\t%.4g\t%.4g\t%s\t%s', q, e, st, v, se, c, r, r / 1e-4, ck, k)


def run_cpu_hours(lines, f=1):
    """the CPU-hours of the runs whose summaries are LINES (their cpu_seconds rows summed), times the
    speed factor F of the binary that made them, %.6g"""
    s = 0.0
    for l in lines:
        r = l.split('\t')
        if fld(r, 1) == 'cpu_seconds':
            s += num(fld(r, 2))
    return cfmt('%.6g', s * num(f) / 3600)


def drive_projection(T, se, u, c):
    """pan-estimators: Table 3's torque at a stronger drive u projected from u = 0.3 (linear in u),
    with the same noise and cost: "T se cpu_h" """
    return cfmt('%.6g %.4g %.6g', num(T) * num(u) / 0.3, se, c)


def run_cost(scene, summary, fac, args):
    """precision.sh: a committed run's production and equilibration CPU seconds (its cpu_seconds x
    the speed factor FAC, split in the ratio of production to equilibration steps) and its
    production time units; equilibration and dt from its arguments, else its scene:
    "prod_cpu<TAB>eq_cpu<TAB>time" (%.6g)"""
    eq = dt = 0.0
    with open(scene) as f:
        for l in f.read().split('\n'):
            l = re.sub(r'#.*', '', l, count=1)
            if re.match(r'^[ \t]*equilibration[ \t]*=[ \t]*[0-9]+', l):
                eq = num(re.sub(r'.*=[ \t]*', '', l, count=1))
            if re.match(r'^[ \t]*dt[ \t]*=[ \t]*[0-9.eE+-]+', l):
                dt = num(re.sub(r'.*=[ \t]*', '', l, count=1))
    v = {}
    for r in rows(summary):
        v[fld(r, 1)] = fld(r, 2)
    for a in args:
        if a.startswith('equilibration='):
            eq = num(a.split('=', 1)[1])
        if a.startswith('dt='):
            dt = num(a.split('=', 1)[1])
    n = num(v.get('steps', ''))
    c = num(v.get('cpu_seconds', '')) * num(fac)
    p = div(n - eq, n)
    return cfmt('%.6g\t%.6g\t%.6g', c * p, c * (1 - p), (n - eq) * dt)


def run_costs_sum(a):
    """precision.sh: the sums over a group's committed runs of run_cost's three columns, formed run
    by run as the shell did with `plus` (each partial sum printed as awk prints a number and read
    back); A: per run, N SCENE SUMMARY FACTOR and its N arguments: "prod_cpu eq_cpu time" """
    pc = ec = tu = '0'
    i = 0
    while i < len(a):
        n = int(a[i])
        p, e, t = run_cost(a[i + 1], a[i + 2], a[i + 3], a[i + 4:i + 4 + n]).split('\t')
        pc, ec, tu = astr(num(pc) + num(p)), astr(num(ec) + num(e)), astr(num(tu) + num(t))
        i += 4 + n
    return '%s %s %s' % (pc, ec, tu)


def paper_band(path, q):
    """selection: "lo<TAB>hi<TAB>paper" of the first paper-tier claim row of Q in a bands.tsv (columns
    by name; a table without a kind column: every row)"""
    rs = rows(path)
    c = {name: i + 1 for i, name in enumerate(rs[0])} if rs else {}
    for r in rs[1:]:
        if fld(r, 1) == q and fld(r, 2) == 'paper' and ('kind' not in c or fld(r, c['kind']) == 'claim'):
            return fld(r, c['lo']) + '\t' + fld(r, c['hi']) + '\t' + fld(r, c['paper'])
    return None


def precision_row(line_, relmode):
    """precision.sh (issue 38 item 1): for a claim with band [lo, hi], value v +- se and Pan's value,
    the stderr that decides it under issue 37's rule (half the distance of the assumed true value to
    the nearest band edge; or RELMODE x |value|: Pan's 0.5 %) at Pan's value and at ours, and the
    CPU-hours of the plain time average for it: the runs' production variance per CPU second, parts
    from separate simulations combined at their best split, (sum_k sqrt(se_k^2 CPU_k))^2 / se^2,
    plus the equilibration once per run; the longest single simulation if the first group's runs
    share it. LINE: experiment, quantity, lo, hi, paper, value, se, the groups
    "prod_cpu:eq_cpu:time:rel:runs" (space-separated), note"""
    f_ = line_.split('\t')
    ex, q, lo, hi, paper, v, se, note = (fld(f_, i) for i in (1, 2, 3, 4, 5, 6, 7, 9))
    g = fld(f_, 8).split()
    S = EQ = 0.0
    var = num(se) * num(se)
    fixed = 0.0
    pc, ec, rel, nr, s2 = [], [], [], [], []
    for gi in g:
        f = gi.split(':')
        pc.append(f[0]); ec.append(f[1]); rel.append(f[3]); nr.append(f[4])
        if rel[-1] != '-':
            s2.append(pw(num(v) * num(rel[-1]), 2))
            fixed += s2[-1]
        else:
            s2.append(None)
    T = NR_ = 0.0
    for i in range(len(g)):
        if rel[i] == '-':
            s2[i] = var - fixed
        if s2[i] < 0:
            s2[i] = 0.0
        S += sqrt(s2[i] * num(pc[i]))
        EQ += num(ec[i])
        if i == 0:
            T = num(g[0].split(':')[2])
            NR_ = num(nr[0])

    def dist(x):
        return num(lo) - num(x) if lt(x, lo) else (num(x) - num(hi) if gt(x, hi) else
                                                   (num(x) - num(lo) if lt(num(x) - num(lo), num(hi) - num(x)) else num(hi) - num(x)))

    def hours(e):
        if le(e, 0):
            return 'inf'
        return cfmt('%.4g', (S * S / (e * e) + EQ) / 3600)

    def longest(e):
        if le(e, 0):
            return 'inf'
        return cfmt('%.4g', (S * S / (e * e) / NR_ + EQ / NR_) / 3600)
    V, E = num(v), num(se)
    if relmode != '':
        verdict = '-'
        sp = -1 if paper == '-' else num(relmode) * abs(num(paper))
        so = num(relmode) * abs(V)
    else:
        verdict = ('PASS' if ge(V - 2 * E, lo) and le(V + 2 * E, hi) else
                   'FAIL' if lt(V + 2 * E, lo) or gt(V - 2 * E, hi) else 'UNRESOLVED')
        sp = -1 if paper == '-' else dist(paper) / 2
        so = dist(v) / 2
    cnow = 0.0
    for i in range(len(g)):
        cnow += num(pc[i]) + num(ec[i])
    return cfmt('%s\t%s\t%s\t%s\t%s\t%.6g\t%.4g\t%s\t%.3g\t%.3g\t%.6g\t%.3g\t%s\t%s\t%s\t%s', ex, q, lo, hi, paper, v, se, verdict,
                sp, so, T, cnow / 3600, hours(sp), hours(so), longest(sp), note)


PE_COMMANDS = {
    'precision-totals': lambda a: precision_totals(a[0]),
    'half-percent-totals': lambda a: half_percent_totals(a[0]),
    # ladder-row OMEGA "T<TAB>se" PROD_TIME CPU_H MU R
    'ladder-row': lambda a: [ladder_row(a[0], *_pairs(a[1:2]), a[2], a[3], a[4], a[5])],
    'ladder-rows': lambda a: ladder_rows(a[0], a[1]),
    # hold-row L U "drag<TAB>se" "force<TAB>se" PROD_TIME CPU_H MU R F_EXT
    'hold-row': lambda a: [hold_row(a[0], a[1], *_pairs(a[2:4]), *a[4:9])],
    'hold-rows': lambda a: hold_rows(a[0], a[1], a[2]),
    # hold-ratio HOLD L1 U1 L2 U2 NAME [HASIMOTO_NAME]
    'hold-ratio': lambda a: hold_ratio(*a[:6], a[6] if len(a) > 6 else None),
    # hold-cols HOLD L U COL...: those columns of the run's row, tab-separated (nothing if there is none)
    'hold-cols': lambda a: (lambda r: ['\t'.join(fld(r, int(c)) for c in a[3:])] if r else [])(_row_where(a[0], [(1, a[1]), (2, a[2])])),
    # prod-time STEPS ARGS SCENE
    'prod-time': lambda a: [prod_time(a[0], a[1], a[2])],
    # twins KIND STEADY PLAIN OUT FILE...: the twins' table OUT and summary rows
    'twins': lambda a: twins(a[0], a[4:], a[1], a[2], a[3]),
    # ladder-cols LADDER OMEGA COL...: those columns of the drive's row
    'ladder-cols': lambda a: (lambda r: ['\t'.join(fld(r, int(c)) for c in a[2:])] if r else [])(_row_where(a[0], [(1, a[1])])),
    # ladder-steady LADDER OMEGA: the drive's torque scaled to Omega = -0.4 (linear), %.10g
    'ladder-steady': lambda a: [cfmt('%.10g', num(fld(_row_where(a[0], [(1, a[1])]), 2)) * -0.4 / num(a[1]))],
    'pair-periodic-factor': lambda a: [pair_periodic_factor(a[0], a[1])],
    # pair-box-row L l u "drag<TAB>se" F P PAN_F
    'pair-box-row': lambda a: [pair_box_row(a[0], a[1], a[2], *_pairs(a[3:4]), a[4], a[5], a[6])],
    # cols-where FILE C=V[,C=V...] COL...: selection of a row's columns (nothing if no row matches)
    'cols-where': lambda a: (lambda t: [t] if t is not None else [])(cols_where(a[0], a[1].split(','), a[2:])),
    # pair30-rows PAIR_BOXES: the 30^3 rows' drag over the periodic prediction as summary rows
    'pair30-rows': lambda a: ['pair30_drag_over_periodic_l%s\t%s\t%s' % (fld(r, 2), fld(r, 9), fld(r, 10)) for r in rows(a[0])[1:] if eq(fld(r, 1), 30)],
    # periodic-ratio-row P12 P30: the periodic predictions' ratio as awk printed it (%.6g), then %.10g
    'periodic-ratio-row': lambda a: [cfmt('pair_periodic_L12_over_L30\t%.10g\t0', num(astr(num(a[0]) / num(a[1]))))],
    'torque-over-drag': lambda a: [torque_over_drag(a)],
    'tf-ratios': lambda a: tf_ratios(*a[:4]),
    'tf-torque': lambda a: tf_torque(*a[:3]),
    # pan-compare-row LAB Q PAN PAN_THEORY "ours<TAB>se" "ratio<TAB>se"
    'pan-compare-row': lambda a: [pan_compare_row(a[0], a[1], a[2], a[3], *_pairs(a[4:6]))],
    # est-row QUANTITY ESTIMATOR SETUP VALUE SE CPU_H CHECK KEPT
    'est-row': lambda a: [est_row(*a[:8])],
    # rcpu SUMMARY [FACTOR] (SUMMARY - : stdin)
    'rcpu': lambda a: [run_cpu_hours(sys.stdin.read().split('\n') if a[0] in ('-', '/dev/stdin') else open(a[0]).read().split('\n'),
                                     a[1] if len(a) > 1 else 1)],
    # fmt FMT ARG...: C's printf of the arguments (an argument "v<TAB>se" gives two)
    'fmt': lambda a: [cfmt(a[0], *[x for arg in a[1:] for x in arg.split('\t')])],
    # half-pair "v<TAB>se" -> v/2 se/2 as awk prints them
    'half-pair': lambda a: [astr(num(parse_pair(a[0]).v) / 2) + ' ' + astr(num(parse_pair(a[0]).se) / 2)],
    # with-variance-se X DOF -> x and its stderr as a variance from DOF + 1 blocks, x sqrt(2 / DOF), as awk prints it
    'with-variance-se': lambda a: [a[0] + ' ' + astr(num(a[0]) * sqrt(2 / num(a[1])))],
    'drive-projection': lambda a: [drive_projection(*a[:4])],
    # run-costs-sum [N SCENE SUMMARY FACTOR ARG1..ARGN]...: run-cost's columns summed over the runs
    'run-costs-sum': lambda a: [run_costs_sum(a)],
    'paper-band': lambda a: (lambda b: [b] if b is not None else [])(paper_band(a[0], a[1])),
    # plus A B -> a + b as awk prints a number
    'plus': lambda a: [astr(num(a[0]) + num(a[1]))],
    # rel-error SUMMARY Q -> se / |value| of the first row Q (nothing if none)
    'rel-error-of': lambda a: (lambda v: [astr(div(num(v.split('\t')[1]), abs(num(v.split('\t')[0]))))] if v else [])(_lookup(a[0], a[1])),
    # precision-row RELMODE LINE
    'precision-row': lambda a: [precision_row(a[1], a[0])],
    'gk-rotational-friction': lambda a: [gk_rotational_friction(*_pairs(a[0:1]), a[1], a[2]).row('gk_rotational_friction_over_eq18')],
}


# ---------------------------------------------------------------- exp.sh's shared helpers
# The statistics that tools/lib/exp.sh's helpers (emit_mean, emit_pct, block_slope, ...) computed
# with numerics.awk, for every experiment that calls them.

def block_stat(path, lo, hi, kind):
    """exp.sh's block_slope and block_mean: per block of a profile_blocks.tsv (rows block, ...,
    pos, ..., v_x; the header and nan rows left out; blocks in the order of their first row), the
    straight-line slope of v_x against pos over LO <= pos <= HI (KIND slope: line) or the mean of
    v_x over LO < pos < HI (KIND mean); then the blocks' mean and standard error as independent
    samples (mean_se); nan for fewer than 2 blocks. The bins of one profile share the flow's
    fluctuations: the blocks' scatter, not the bins', is the error"""
    order, pts = [], {}
    for n, r in enumerate(rows(path)):
        if n == 0 or fld(r, 5) == 'nan':
            continue
        p = fld(r, 3)
        inside = (ge(p, lo) and le(p, hi)) if kind == 'slope' else (gt(p, lo) and lt(p, hi))
        if inside:
            k = fld(r, 1)
            if k not in pts:
                pts[k] = ([], [])
                order.append(k)
            pts[k][0].append(p)
            pts[k][1].append(fld(r, 5))
    if kind == 'slope':
        s = [line(*pts[k]).slope for k in order]
    else:
        s = [mean(pts[k][1]) for k in order]
    if len(order) < 2:
        return Val()
    return mean_se(s)


def max_rel_dev(path, lo, hi):
    """exp.sh's max_rel_dev: the largest relative deviation |x - mean| / mean of a profile's
    density over the bins with LO <= pos <= HI (the first if tied), its error that bin's
    stderr / mean (the mean's own error neglected; num_max_rel_dev)"""
    d, e = [], []
    for r in rows(path):
        if fld(r, 1).startswith('#') or fld(r, 1) == 'pos':
            continue
        if ge(fld(r, 1), lo) and le(fld(r, 1), hi):
            d.append(fld(r, 2)); e.append(fld(r, 3))
    m = mean(d)
    best = be = 0.0
    for x, s in zip(d, e):
        dv = abs((num(x) - num(m)) / num(m))
        if dv > best:
            best, be = dv, num(s) / num(m)
    return Val(best, be)


def wall_stress(forces, lx):
    """exp.sh's couette_viscosity: the shear stress of the m = 0 Couette channel from the x forces
    on its walls (bottom_inner, bottom_outer, top_inner, top_outer: "F<TAB>se" each),
    (F_bottom - F_top) / (2 LX), the errors added linearly (at m = 0 the walls' forces are
    opposite step by step and a wall's two layers move together; at m > 0 an upper bound)"""
    xs = [(1 if i < 2 else -1) * num(parse_pair(f).v) for i, f in enumerate(forces)]
    o = sum_linear(xs, [parse_pair(f).se for f in forces])
    return cfmt('%.10g %.4g', o.v / (2 * num(lx)), o.se / (2 * num(lx)))


def pct_from(a, b):
    """100 (a / b - 1), a's deviation from b in per cent, first-order error of independent a, b
    (exp.sh's emit_pct; b may be exact)"""
    x, y = _pair_or_number(a), _pair_or_number(b)
    r = v_ratio(x.v, x.se, y.v, y.se)
    if isnan_text(r.v):
        return Val()
    return v_scale(num(r.v) - 1, r.se, 100)


def lattice_tag(kp, kq, digits):
    """mai-duy-2019's suspensions (exp.sh's lattice_pair): the paper's KP^3 colloids of 6 particles
    among 13500 solvent particles in 15^3 run as KQ^3 colloids in a box of side 15 KQ / KP: the tag
    "phi" + phi = 6 KP^3 / (13500 + 6 KP^3) to DIGITS decimals, and the side (%.10g): "tag L" """
    k = num(kp)
    phi = 6 * pw(k, 3) / (13500 + 6 * pw(k, 3))
    return cfmt('phi%.*f %.10g', digits, phi, 15 * num(kq) / k)


# ---------------------------------------------------------------- simulation arguments
# What a run.sh's declared simulations compute from its tier's settings (issue 40 item 5: no
# arithmetic in a shell string); each prints the argument as the awk it replaces did.

def steps_for(t, dt):
    """the steps of length DT that make the time T, rounded to the nearest: int(t / dt + 0.5)"""
    return cfmt('%d', num(t) / num(dt) + 0.5)


def sample_every(interval, dt):
    """the sampling stride in steps for a sampling INTERVAL in time at step DT: the nearest
    integer to interval / dt, at least 1"""
    e = int(num(interval) / num(dt) + 0.5)
    return cfmt('%d', 1 if e < 1 else e)


def tcaf_axis_nmax(k, cap=31):
    """mai-duy-2019 fig04's high-k TCAF runs: the largest wave-vector index per axis, two past
    kq (4 pi / 3)^(1/3) (the index of the colloid lattice's equal-volume sphere, kq colloids per
    axis), at most CAP"""
    n = int(num(k) * pw(4 * 3.14159265358979 / 3, 1 / 3)) + 2
    return astr(min(n, cap))


def geometric_mid(a, b, fmt):
    """a bisection's next trial in a bracket spanning decades: the geometric middle sqrt(a b),
    printed with FMT (the stability map's dt)"""
    return cfmt(fmt, sqrt(num(a) * num(b)))


def octahedron_inertia(m, d):
    """the moment of inertia of a rigid octahedron of total mass M whose six sites sit at D from
    its centre: I = (2/3) M d^2 (%.10g)"""
    return cfmt('%.10g', 2 * num(m) * num(d) * num(d) / 3)


def sigmas(a, sa, b, sb):
    """(a - b) / sqrt(sa^2 + sb^2): a difference in units of its standard error (independent a and
    b; b may be an exact number, sb = 0); nan without an error"""
    if _nan4(a, sa, b, sb):
        return 'nan'
    d = sqrt(sq(sa) + sq(sb))
    return 'nan' if d == 0 else (num(a) - num(b)) / d


def _pairs_or_numbers(xs):
    """_pairs of "value<TAB>stderr" entries or exact numbers"""
    return _pairs(xs, _pair_or_number)


def _pair_or_number(x):
    """ "value<TAB>stderr" (as get gives it), or a number (exact: stderr 0)"""
    o = parse_pair(x)
    return Val(o.v, o.se if '\t' in x else '0')


HELPER_COMMANDS = {
    # block-stat PROFILE_BLOCKS LO HI slope|mean -> "value<TAB>se"
    'block-stat': lambda a: [block_stat(a[0], a[1], a[2], a[3]).pair()],
    'max-rel-dev': lambda a: [max_rel_dev(a[0], a[1], a[2]).pair()],
    # wall-stress LX F_BOTTOM_INNER F_BOTTOM_OUTER F_TOP_INNER F_TOP_OUTER -> "tau tau_se"
    'wall-stress': lambda a: [wall_stress(a[1:5], a[0])],
    # pct A B, minus A B (A, B "v<TAB>se" or a number) -> "value<TAB>se"
    'pct': lambda a: [pct_from(a[0], a[1]).pair()],
    'minus': lambda a: [(lambda x, y: v_diff(x.v, x.se, y.v, y.se))(_pair_or_number(a[0]), _pair_or_number(a[1])).pair()],
    # mean-se-row NAME V...: the mean of independent runs' values, its standard error (0 for one run)
    'mean-se-row': lambda a: [(lambda o: o.row(a[0]))(mean_se(a[1:]) if len(a) != 2 else Val(mean(a[1:]), 0))],
    'lattice-tag': lambda a: [lattice_tag(a[0], a[1], a[2])],
}


ARGS_COMMANDS = {
    # sigmas NAME A B: (a - b) / sqrt(sa^2 + sb^2) as a row (%.4g, stderr 0); A, B "v<TAB>se" or a number
    'sigmas': lambda a: [cfmt('%s\t%.4g\t0', a[0], sigmas(*_pairs_or_numbers(a[1:3])))],
    'steps-for': lambda a: [steps_for(a[0], a[1])],
    'sample-every': lambda a: [sample_every(a[0], a[1])],
    'tcaf-axis-nmax': lambda a: [tcaf_axis_nmax(a[0])],
    'geometric-mid': lambda a: [geometric_mid(a[0], a[1], a[2])],
    'octahedron-inertia': lambda a: [octahedron_inertia(a[0], a[1])],
    # sum-fmt FMT A B -> FMT of a + b (a position offset by a small distance, %.15f)
    'sum-fmt': lambda a: [cfmt(a[0], num(a[1]) + num(a[2]))],
}


# ---------------------------------------------------------------- the command line

def _guarded(pair):
    """a "value<TAB>se" whose value is nan or infinite: nothing to read a curve at"""
    return pair.split('\t')[0] in ('nan', '-nan', 'inf', '-inf')


def _lookup(path, q):
    for r in rows(path):
        if fld(r, 1) == q:
            return fld(r, 2) + '\t' + fld(r, 3)
    return None


def cmd_lookup(a):
    """lookup FILE Q [WHAT]: "value<TAB>stderr" of the first row named Q; exit 1 if none (WHAT:
    the error message's subject)"""
    v = _lookup(a[0], a[1])
    if v is None:
        if len(a) > 2:
            sys.stderr.write('%s: no %s in %s\n' % (a[2], a[1], a[0]))
        return 1
    return [v]


def _two(op):
    return lambda a: [op(*(parse_pair(a[0]).v, parse_pair(a[0]).se, parse_pair(a[1]).v, parse_pair(a[1]).se)).pair()]


COMMANDS = {
    'lookup': cmd_lookup,
    # "v<TAB>se" "v<TAB>se" -> "v<TAB>se"
    'diff': _two(v_diff),
    'sum': _two(v_sum),
    'ratio': _two(v_ratio),
    'product': _two(v_product),
    # scale "v<TAB>se" F -> f (v +- se)
    'scale': lambda a: [v_scale(parse_pair(a[0]).v, parse_pair(a[0]).se, a[1]).pair()],
    # quotient A B -> a / b (%.12g: an exact factor to scale by)
    'quotient': lambda a: [cfmt('%.12g', div(num(a[0]), num(a[1])))],
    # curve TCAF_ETA [HIGH_K_TCAF_ETA]
    'curve': lambda a: tcaf_curve(a),
    # normalise CURVE C0
    'normalise': lambda a: normalise_curve(a[0], a[1]),
    # keff CURVE ETA SE TAG -> k_eff_TAG, lambda_eff_TAG, eta_eff_TAG rows
    'keff': lambda a: keff(a[0], a[1], a[2], a[3]),
    # k-eff CURVE "v<TAB>se" -> the k_eff pair (nan for a nan or infinite value)
    'k-eff': lambda a: ['nan\tnan'] if _guarded(a[1]) else
        [keff(a[0], parse_pair(a[1]).v, parse_pair(a[1]).se, 'x')[0].split('\t', 1)[1]],
    # interp CURVE "k<TAB>se" -> the curve's eta there (nan for a nan or infinite k)
    'interp': lambda a: ['nan\tnan'] if _guarded(a[1]) else
        [interp(*_columns(a[0], 1, 4, 5), parse_pair(a[1]).v, parse_pair(a[1]).se).pair()],
    # phi-row TAG COUNT N -> phi_TAG, count / n (the volume fraction of the bodies' particles)
    'phi-row': lambda a: [cfmt('phi_%s\t%.10g\t0', a[0], div(num(a[1]), num(a[2])))],
    # rho-total RHO NC L -> rho + 6 nc / L^3 (the bodies of mass 6 in the density)
    'rho-total': lambda a: [cfmt('%.10g', num(a[0]) + 6 * num(a[1]) / pw(num(a[2]), 3))],
    # sum-column Q FMT FILE... -> FMT of the sum of column 2 over the rows named Q, in order
    'sum-column': lambda a: [cfmt(a[1], _sum_column(a[0], a[2:]))],
    # grid A PHI F_P F_S F_T C_EXP C_TWO_MODE C_INTEGRAL F0_EXP F0_TWO_MODE F0_INTEGRAL FREE SOLVENT
    'grid': lambda a: ['# a\tphi\tD\tE\tK\tF\tk_eff\tse\teta_eff\tse (grid.awk)'] if a == ['--header'] else tcaf_grid(a[0], a[1], a[2], a[3], a[4],
                                {'exp': a[5], 'two_mode': a[6], 'integral': a[7]},
                                {'exp': a[8], 'two_mode': a[9], 'integral': a[10]}, a[11], a[12]),
    # readings-table2-rows SUMMARY: the Table 2 rows (a = 3.53) under their own names
    'readings-table2-rows': lambda a: [re.sub(r'_a3\.53_', '_', fld(r, 1), count=1) + '\t' + fld(r, 2) + '\t' + fld(r, 3)
                                       for r in rows(a[0]) if re.match(r'^reading_[a-e]_(k_eff|eta_eff)_a3\.53_phi', fld(r, 1))],
    'largest-sigmas': lambda a: largest_sigmas(a[0], a[1]),
    'log-ratios': lambda a: log_ratios(int(a[0]), a[1], a[2]),
    # geometric-mean Q KIND < logs
    'geometric-mean': lambda a: geometric_mean_rows(a[0], a[1], [l.split('\t')[0] for l in sys.stdin.read().split('\n')[:-1]]),
    'eta0-ratios': lambda a: eta0_one_minus_phi_rows(a[0], a[1], a[2]),
    # readings-tables OUT PAPER2 TIER "AS" "READINGS"
    'readings-tables': lambda a: readings_tables(a[0], a[1], a[2], a[3].split(), a[4].split()) or [],
    # readings-grid PAPER2 SUMMARY GRID_ROWS GRID_OUT -> summary rows
    'readings-grid': lambda a: readings_grid_decision(a[0], a[1], a[2], a[3]),
    # etak CURVE LAMBDA NAME -> NAME, eta(k = 2 pi / lambda)
    'etak': lambda a: eta_at_wavelength(a[0], a[1], a[2]),
    # keff-lambda CURVE ETA SE TAG -> lambda_tcaf_TAG (the lambda_eff row of keff)
    'keff-lambda': lambda a: ['lambda_tcaf_' + keff(a[0], a[1], a[2], a[3])[1].split('_', 2)[2]],
    'tab02-data-row': lambda a: tab02_data_row(a[0], a[1], a[2]),
    'tab02-table': lambda a: tab02_table(a[0], a[1]),
    'solvent-at-paper-keff': lambda a: solvent_at_paper_keff(a[0], a[1]),
    # rename SUMMARY OLD NEW [OLD NEW...]
    'rename': lambda a: rename_rows(a[0], a[1:]),
    # summary-diff SUMMARY A B Q
    'summary-diff': lambda a: summary_diff(a[0], a[1], a[2], a[3]),
    # tolerance-to-pass SUMMARY Q THEORY OUT
    'tolerance-to-pass': lambda a: tolerance_to_pass(a[0], a[1], a[2], a[3]),
    'tab01-projected-cpu-hours': lambda a: tab01_projected_cpu_hours(a[0], a[1], a[2]),
    # tab01-tables SUMMARY PAPER1 TABLE1_OUT LAMBDA_OUT
    'tab01-tables': lambda a: _write2(tab01_tables(a[0], a[1]), a[2], a[3]),
    # r-half < fit-line output
    'r-half': lambda a: r_half([l.split('\t') for l in sys.stdin.read().split('\n')[:-1]]),
    # colloid-radius "R1 R2 ..." D
    'colloid-radius': lambda a: colloid_radius_rows(a[0].split(), a[1]),
    'shear-rate-at-pe': lambda a: shear_rate_at_pe(a[0], a[1]),
    'lambda-cube': lambda a: lambda_cube(a[0], a[1]),
    'lambda-sphere': lambda a: lambda_sphere(a[0], a[1]),
    'fig04-ratios': lambda a: fig04_ratios(a[0], a[1]),
    'fig04-eta-r-row': lambda a: fig04_eta_r_row(a[0], a[1]),
    'cost-per-kilo': lambda a: cost_per_kilo(a[0], a[1], a[2]),
    'ladder-cost-per-dt': lambda a: ladder_cost_per_dt(a[0]),
    'gw-temperature-ladder': lambda a: gw_temperature_ladder(a[0], a[1]),
    'dt-within-1pct': lambda a: dt_within_1pct(a[0]),
    # rel-error E ES R RS
    'rel-error': lambda a: rel_error(*a[:4]),
    'tolerance-summary': lambda a: tolerance_summary(a[0]),
    'true-error-slopes': lambda a: true_error_slopes(a[0]),
    'wall-slip': lambda a: wall_slip(*a[:4]),
    'ik-bulk-stress': lambda a: ik_bulk_stress(a[0], a[1]),
    'bulk-density': lambda a: bulk_density(a[0], a[1]),
    'first-defined': lambda a: first_defined(a[0], int(a[1])),
    # diff-div "v<TAB>se" "v<TAB>se" C -> (x - y) / c
    'diff-div': lambda a: [(lambda o: v_div(o.v, o.se, a[2]))(v_diff(parse_pair(a[0]).v, parse_pair(a[0]).se,
                                                                  parse_pair(a[1]).v, parse_pair(a[1]).se)).pair()],
    'wall-minus-lees-edwards': lambda a: wall_minus_lees_edwards(*a[:4]),
    # keff-rows CURVE ETA SE SUFFIX -> k_eff<SUFFIX>, lambda_eff<SUFFIX> (SUFFIX may be empty)
    'keff-rows': lambda a: [r.split('\t', 1)[0][:-2] + a[3] + '\t' + r.split('\t', 1)[1] for r in keff(a[0], a[1], a[2], 'x')[:2]],
    # fraction COUNT N -> count / n (%.10g)
    'fraction': lambda a: [cfmt('%.10g', div(num(a[0]), num(a[1])))],
    # density-fields MAP L CX CY REX N0
    'density-fields': lambda a: density_fields(*a[:6]),
    # residual-floor-free Q L CX CY REX N0 MAP MAP MAP...
    'residual-floor-free': lambda a: residual_floor_free(*a),
    # fields-mean-row P M < "residual divu nb U" rows
    'fields-mean-row': lambda a: fields_mean_row(a[0], a[1], sys.stdin.read().split('\n')[:-1]),
    'force-balance': lambda a: force_balance(a[0], a[1], a[2]),
    'eos-slope': lambda a: eos_slope(a[0], a[1]),
    'sound-speed': lambda a: ['sound_speed_m1\t' + (lambda x: v_sqrt(x.v, x.se))(parse_pair(a[0])).pair('%.6g', '%.3g')],
    'fig08-mach': lambda a: fig08_mach(a[0], a[1]),
    'fig08-mach-rows': lambda a: ['mach_m1_P%s\t%s\t%s' % (fld(r, 1), fld(r, 2), fld(r, 3)) for r in rows(a[0])[1:] if fld(r, 1) in ('0.1', '1.0')],
    'fig08-growths': lambda a: fig08_growths(a[0]),
    # dt-scan SUMMARY "DTS" OUT
    'dt-scan': lambda a: dt_scan(a[0], a[1], a[2]),
    # thinning-row RATE A D "eta<TAB>se" "eta0<TAB>se"
    'thinning-row': lambda a: thinning_row(*a[:5]),
    # significance SUMMARY Q NAME
    'significance': lambda a: significance(a[0], a[1], a[2]),
    'relative-thinning': lambda a: relative_thinning(a[0], a[1], a[2]),
    'within-1pct-best': lambda a: within_1pct_best(a[0], a[1], a[2]),
    'abs-max': lambda a: abs_max(a[0], a[1]),
    # mean-list Q "V1 V2 ..."
    'mean-list': lambda a: mean_list(a[0], a[1].split()),
    'fig12-row': lambda a: fig12_row(*a[:4]),
    'slope-rows': lambda a: slope_rows(a[0], a[1]),
    # fig07-drag P N H DRAG U ETA A: summary rows on stdout, the drag.tsv row on stderr
    'fig07-drag': lambda a: _stderr_second(fig07_drag(*a[:7])),
    'solvent-radius': lambda a: solvent_radius(a[0]),
    # times A B -> a b as awk prints a number
    'times': lambda a: [astr(num(a[0]) * num(a[1]))],
    # values NAME... < rows: the last value of each name
    'values': lambda a: values(sys.stdin.read().split('\n'), a),
    # couette-growth TS NAME OUTDIR < the runs' vx_blocks rows
    'couette-growth': lambda a: couette_growth(sys.stdin.read().split('\n')[:-1], a[0], a[1], a[2]),
    # methods/stability-map
    'bisect-seed-row': lambda a: bisect_seed_row(*a[:6]),
    'bisect-dt-max': lambda a: bisect_dt_max(*a[:4]),
    # dt-max-slope DT_MAX Q FAMILY FROM TO
    'dt-max-slope': lambda a: dt_max_slope(*a[:5]),
    # dt-max-corrected DT_MAX FAMILY FROM TO Q NAME_EXPONENT NAME_BETA NAME_CHI2
    'dt-max-corrected': lambda a: dt_max_corrected(*a[:8]),
    # dt-max-paired SEEDS FAMILY FROM TO Q NAME
    'dt-max-paired': lambda a: dt_max_paired(*a[:6]),
    # dt-max-ratio DT_MAX Q F1 V1 F2 V2
    'dt-max-ratio': lambda a: dt_max_ratio_row(*a[:6]),
    'gas-weight-ratio': lambda a: gas_weight_ratio(a[0], a[1]),
    'family-rows': lambda a: family_rows(a[0]),
    'trial-rows': lambda a: trial_rows(a[0]),
    'cpu-from-times': lambda a: cpu_from_times(a[0]),
    # equal-error LADDER ESTAR
    'equal-error': lambda a: equal_error(a[0], a[1]),
    # dt-max-rows DT_MAX: its rows as summary rows dt_max_<family>_<param><value>
    'dt-max-rows': lambda a: ['dt_max_%s_%s%s\t%s\t%s' % (fld(r, 1), fld(r, 2), fld(r, 3), fld(r, 4), fld(r, 5)) for r in rows(a[0])[1:]],
    # at-most X Y: exit 0 if x <= y (numbers)
    'at-most': lambda a: 0 if le(num(a[0]), num(a[1])) else 1,
    # quotient6 A B -> a / b (%.6g)
    'quotient6': lambda a: [cfmt('%.6g', div(num(a[0]), num(a[1])))],
    # times6 A B -> a b (%.6g)
    'times6': lambda a: [cfmt('%.6g', num(a[0]) * num(a[1]))],
}

COMMANDS.update(PAN_COMMANDS)
COMMANDS.update(ARGS_COMMANDS)
COMMANDS.update(HELPER_COMMANDS)
COMMANDS.update(PE_COMMANDS)


def _stderr_second(pair):
    sys.stderr.write(''.join(l + '\n' for l in pair[1]))
    return pair[0]


def _write2(tables, p1, p2):
    for t, p in zip(tables, (p1, p2)):
        with open(p, 'w') as f:
            f.write(''.join(l + '\n' for l in t))
    return []


def _columns(path, *cols):
    """the given columns of every row of a file, as lists"""
    rs = rows(path)
    return [[fld(r, c) for r in rs] for c in cols]


def _sum_column(q, paths):
    s = 0.0
    for p in paths:
        for r in rows(p):
            if fld(r, 1) == q:
                s += num(fld(r, 2))
    return s


def main(argv):
    if len(argv) < 2 or argv[1] not in COMMANDS:
        sys.stderr.write('usage: analyse SUBCOMMAND ARGS... (subcommands: %s)\n' % ' '.join(sorted(COMMANDS)))
        return 2
    try:
        res = COMMANDS[argv[1]](argv[2:])
    except (IndexError, KeyError) as e:
        sys.stderr.write('analyse %s: bad arguments %s (%s)\n' % (argv[1], argv[2:], e))
        return 2
    except OSError as e:
        sys.stderr.write('analyse %s: %s\n' % (argv[1], e))
        return 1
    if isinstance(res, int):
        return res
    sys.stdout.write(''.join(l + '\n' for l in res))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
