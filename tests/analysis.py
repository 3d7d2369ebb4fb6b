#!/usr/bin/env python3
"""tests/analysis.py - tools/analysis.py, the experiments' analysis layer: every statistic on
synthetic data whose answer is known in closed form, and the emulation of mawk's number
formatting and comparisons on which the committed tables' bytes depend (checked against mawk
itself where it is installed). Prints PASS/FAIL per named check and "N passed, M failed"; exit
status 1 on any failure. ANALYSIS_PY: another copy of the module to test (a mutant).

Tolerances: inputs of a few significant digits give results exact up to the roundings of at
most ~20 operations, each within half an ulp (1.1e-16 relative), so a relative 1e-13 holds every
correct result and fails any wrong formula (n for n - 1, a missing square root, an unweighted
fit) by far more.
"""
import importlib.util
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
path = os.environ.get('ANALYSIS_PY', os.path.join(HERE, '..', 'tools', 'analysis.py'))
spec = importlib.util.spec_from_file_location('analysis', path)
A = importlib.util.module_from_spec(spec)
spec.loader.exec_module(A)

passed = failed = 0


def check(name, cond, detail=''):
    global passed, failed
    if cond:
        passed += 1
        print('PASS ' + name)
    else:
        failed += 1
        print('FAIL %s: %s' % (name, detail))


def close(name, got, want, rel=1e-13):
    g = A.num(got) if isinstance(got, str) else got
    if isinstance(want, str) and want == 'nan':
        check(name, A.isnan_text(got), 'got %r, want nan' % (got,))
        return
    ok = not math.isnan(g) and abs(g - want) <= rel * (abs(want) if want != 0 else 1)
    check(name, ok, 'got %r, want %r' % (got, want))


def same(name, got, want):
    check(name, got == want, 'got %r, want %r' % (got, want))


tmp = tempfile.mkdtemp(prefix='dpd-analysis-')


def tsv(name, text):
    p = os.path.join(tmp, name)
    with open(p, 'w') as f:
        f.write(text)
    return p


# ---- awk's numbers and text (mawk 1.3.4)
same('astr: an integer value prints as an integer', A.astr(3.0), '3')
same('astr: -0 prints as 0', A.astr(-0.0), '0')
same('astr: a fraction by %.6g', A.astr(0.1 + 0.2), '0.3')
same('astr: 2^31 is past mawk\'s integers: %.6g', A.astr(2.0 ** 31), '2.14748e+09')
same('astr: -(2^31 - 1) still an integer', A.astr(-2147483647.0), '-2147483647')
same('astr: a field\'s text unchanged', A.astr('1.50'), '1.50')
same('cfmt: NaN as nan', A.cfmt('%.4g', float('nan')), 'nan')
same('cfmt: a NaN with its sign bit as -nan (glibc)', A.cfmt('%.4g', -float('nan')), '-nan')
same('cfmt: 0/0 is -nan as on x86', A.cfmt('%.3f', A.div(0.0, 0.0)), '-nan')
same('cfmt: %d of 3e9 clamps to 2^31 - 1 (mawk d_to_I)', A.cfmt('%d', 3e9), '2147483647')
same('cfmt: %d of NaN is -(2^31 - 1)', A.cfmt('%d', float('nan')), '-2147483647')
same('cfmt: %d truncates', A.cfmt('%d', -2.7), '-2')
same('cfmt: %.*f takes the precision from the arguments', A.cfmt('%.*f +- %.*f', 2, '3.14159', 2, 0.005), '3.14 +- 0.01')
same('cfmt: a numeric conversion of text reads its leading number', A.cfmt('%.2f', '2.5abc'), '2.50')
same('cfmt: %s of a number is astr', A.cfmt('%s|%s', 2.0, 0.5), '2|0.5')
close('num: leading number of text', A.num('3.5e1x'), 35.0)
close('num: empty text is 0', A.num(''), 0.0)
check('num: the text nan is NaN', math.isnan(A.num('nan')))
same('num: -inf', A.num('-inf'), -math.inf)
check('eq: NaN equals any number (mawk compare() returns 0)', A.eq(float('nan'), 0))
check('le/ge: NaN <= x and NaN >= x hold', A.le(float('nan'), 1) and A.ge(float('nan'), 1))
check('ne: NaN != x does not hold', not A.ne(float('nan'), 5))
check('gt: the field "nan" compares as text ("nan" > "0")', A.gt('nan', 0))
check('gt: the field "-nan" compares as text ("-nan" < "0")', not A.gt('-nan', 0))
check('gt: numeric-looking fields compare as numbers ("10" > "9")', A.gt('10', '9'))
check('isnan_text: nan, -nan, NaN', A.isnan_text('nan') and A.isnan_text('-nan') and A.isnan_text('NaN'))
check('isnan_text: inf is not nan', not A.isnan_text('inf'))

# the emulation against mawk itself: print and printf of the same numbers
mawk = shutil.which('mawk')
if mawk:
    xs = ['0.1', '-2.5', '1e-7', '123456.75', '2147483647', '2147483648', '-0', '1e300', '3', '0.30000000000000004',
          '6.02214076e23', '-1.5e-300', '7']
    prog = ('{ x = $1 + 0; print x; printf "%.10g|%.4g|%d|%.3f|%e|%s\\n", x, x, x, x, x, x; '
            'y = x * 3 / 7; print y, (y < 0.5), (x == 3) }')
    out = subprocess.run([mawk, prog], input='\n'.join(xs) + '\n', capture_output=True, text=True).stdout.split('\n')
    mine = []
    for s in xs:
        x = A.num(s) + 0.0
        mine.append(A.astr(x))
        mine.append(A.cfmt('%.10g|%.4g|%d|%.3f|%e|%s', x, x, x, x, x, x))
        y = x * 3 / 7
        mine.append(A.astr(y) + ' ' + ('1' if A.lt(y, 0.5) else '0') + ' ' + ('1' if A.eq(x, 3) else '0'))
    same('print and printf of %d numbers as mawk prints them' % len(xs), mine, out[:len(mine)])
else:
    print('SKIP mawk not installed: the emulation is checked against the fixed cases above only')

# ---- error propagation (first order, independent operands)
o = A.v_diff('5', '0.3', '2', '0.4')
close('v_diff: value', o.v, 3.0)
close('v_diff: errors in quadrature', o.se, 0.5)
o = A.v_sum(1.5, 0.6, 2.5, 0.8)
close('v_sum: value', o.v, 4.0)
close('v_sum: errors in quadrature', o.se, 1.0)
o = A.v_ratio('6', '0.3', '2', '0.08')
close('v_ratio: value', o.v, 3.0)
close('v_ratio: relative errors in quadrature', o.se, 3.0 * math.sqrt(0.05 ** 2 + 0.04 ** 2))
o = A.v_product('3', '0.09', '4', '0.16')
close('v_product: value', o.v, 12.0)
close('v_product: relative errors in quadrature', o.se, 12.0 * 0.05)
o = A.v_scale('2', '0.1', '-3')
close('v_scale: value', o.v, -6.0)
close('v_scale: error times |f|', o.se, 0.3)
o = A.v_inverse(2, '4', '0.2')
close('v_inverse: c / a', o.v, 0.5)
close('v_inverse: |c| sa / a^2', o.se, 2 * 0.2 / 16)
o = A.v_rel1(10.0, '5', '0.5')
close('v_rel1: a\'s relative error on x', o.se, 1.0)
o = A.v_div('9', '0.3', '3')
close('v_div: (a +- sa) / c', o.v, 3.0)
close('v_div: error sa / |c|', o.se, 0.1)
o = A.v_lin2(2, '1', '0.3', -1, '4', '0.4')
close('v_lin2: w1 a + w2 b', o.v, -2.0)
close('v_lin2: errors weighted in quadrature', o.se, math.sqrt(0.36 + 0.16))
o = A.v_sqrt('16', '0.8')
close('v_sqrt: value', o.v, 4.0)
close('v_sqrt: error sa / (2 sqrt a)', o.se, 0.1)
same('a nan operand gives nan nan', A.v_ratio('nan', '1', '2', '0.1').pair(), 'nan\tnan')
same('Val.pair: %.10g and %.4g', A.Val(1 / 3, 2 / 3).pair(), '0.3333333333\t0.6667')
close('quad: errors in quadrature', A.quad([3, 4, 12]), 13.0)

# ---- means, jackknife, weighted mean
o = A.mean_se(['1', '2', '3', '4'])
close('mean_se: mean', o.v, 2.5)
close('mean_se: sample sd / sqrt(n)', o.se, math.sqrt(5 / 3 / 4))
same('mean_se: one value has no error', A.mean_se(['2']).se, 'nan')
same('mean: a nan value makes the mean nan', A.mean(['1', 'nan']), 'nan')
# cancellation: a two-pass variance keeps the small scatter of large values
o = A.mean_se([1e9 + 1, 1e9 + 2, 1e9 + 3])
close('mean_se: two passes, no cancellation at 1e9', o.se, math.sqrt(1 / 3), 1e-6)
o = A.jackknife_se(['1', '2', '3'])
close('jackknife_se: mean of the leave-one-out estimates', o.v, 2.0)
close('jackknife_se: sqrt((n - 1) / n sum (x - m)^2)', o.se, math.sqrt(2 / 3 * 2))
o = A.wmean_se(['1', '3', '100', '7'], ['1', '1', '0', 'nan'])
close('wmean_se: inverse-variance weights, se <= 0 and nan left out', o.v, 2.0)
close('wmean_se: 1 / sqrt(sum w)', o.se, 1 / math.sqrt(2))
o = A.wmean_se(['1', '4'], ['1', '2'])
close('wmean_se: unequal weights', o.v, (1 + 4 / 4) / (1 + 1 / 4))
o = A.sum_linear(['1', '2'], ['0.1', '0.2'])
close('sum_linear: errors added linearly', o.se, 0.3)

# ---- fits
ln = A.line(['0', '1', '2', '3', '4'], [2 + 3 * x for x in range(5)])
close('line: slope of an exact line', ln.slope, 3.0)
close('line: intercept of an exact line', ln.icpt, 2.0)
close('line: zero residuals, zero error', ln.slope_se, 0.0)
ln = A.line(['0', '1', '2'], ['0', '2', '1'])
close('line: least-squares slope', ln.slope, 0.5)
close('line: least-squares intercept', ln.icpt, 0.5)
close('line: slope error from the residuals (n - 2 dof)', ln.slope_se, math.sqrt(0.75))
close('line: intercept error from the residuals', ln.icpt_se, math.sqrt(1.25))
same('line: two points have no residual error', A.line(['0', '1'], ['0', '1']).slope_se, 'nan')
same('line: equal x give nan', A.line(['1', '1', '1'], ['0', '1', '2']).slope, 'nan')
ln = A.wline(['0', '1'], ['1', '3'], ['1', '1'])
close('wline: slope through two points', ln.slope, 2.0)
close('wline: slope error sqrt(sw / d)', ln.slope_se, math.sqrt(2.0))
close('wline: intercept error sqrt(sxx / d)', ln.icpt_se, 1.0)
ln = A.wline(['0', '1', '2'], ['0', '1', '0'], ['0.001', '0.001', '1000'])
check('wline: a point of large error barely counts (slope ~ 1, unweighted 0)', abs(ln.slope - 1) < 1e-6, ln.slope)
ln = A.wline(['0', '1', '2', '3'], ['0', '1', 'nan', '5'], ['1', '1', '1', '0'])
same('wline: nan rows and se <= 0 left out', ln.n, 2)
o = A.wpoly2(['0', '1', '2', '3'], [1 + 2 * x + 3 * x * x for x in range(4)], ['1', '1', '1', '1'])
close('wpoly2: c0 of an exact parabola', o.v, 1.0, 1e-12)
# c0's error for 3 points at x = -1, 0, 1 with se = 1: the inverse normal matrix's (0, 0) element is 1
o = A.wpoly2(['-1', '0', '1'], ['2', '1', '2'], ['1', '1', '1'])
close('wpoly2: c0 error from the inverse normal matrix', o.se, 1.0)
same('wpoly2: fewer than 3 points give nan', A.wpoly2(['0', '1'], ['0', '1'], ['1', '1']).v, 'nan')
close('det3: the determinant', A.det3(2, 0, 1, 1, 3, 2, 1, 1, 1), 2 * (3 - 2) - 0 + 1 * (1 - 3))

# ---- interpolation, crossing, intervals
o = A.interp(['0', '1', '2'], ['0', '2', '4'], ['0.1', '0.1', '0.1'], '1.5', '0.05')
close('interp: linear between the bracketing points', o.v, 3.0)
close('interp: error from the points (1 - f, f) and through the slope from x\'s', o.se,
      math.sqrt(0.05 ** 2 + 0.05 ** 2 + (2 * 0.05) ** 2))
same('interp: outside the table is nan', A.interp(['0', '1'], ['0', '1'], ['0', '0'], '1.5', '0').pair(), 'nan\tnan')
o = A.crossing(['0', '1', '2', '3', '4'], [str(10 - 2 * x) for x in range(5)], ['0'] * 5, '5', '0.2')
close('crossing: where the table reaches yq', o.v, 2.5)
close('crossing: yq\'s error through dx/dy', o.se, 0.1)
o = A.crossing(['0', '1', '2'], ['0', '2', '0'], ['0', '0', '0'], '1', '0')
close('crossing: the first crossing from x[1]', o.v, 0.5)
o = A.crossing(['0', '1', '2'], ['0', '1', '2'], ['0', '0', '0'], '1', '0')
close('crossing: a tabulated point equal to yq is a crossing (<= 0)', o.v, 1.0)
same('crossing: never reached is nan', A.crossing(['0', '1'], ['0', '1'], ['0', '0'], '5', '0').v, 'nan')
close('uniform_se: (hi - lo) / sqrt(12)', A.uniform_se('0.01', '0.02'), 0.01 / math.sqrt(12))

# ---- the TCAF curves (mai-duy-2019)
free = tsv('free.tsv', '# comment\nk\tn2\tvectors\teta\teta_se\n0.5\t1\t6\t20\t0.5\n1.0\t2\t12\tnan\tnan\n'
                       '1.5\t3\t8\t10\t0.5\n')
hk = tsv('hk.tsv', 'k\tn2\tvectors\teta\teta_se\n1.0\t1\t6\t99\t1\n1.5\t1\t6\t98\t1\n3.0\t4\t6\t5\t0.25\n')
same('tcaf_curve: defined shells, continued above the first file\'s largest k',
     A.tcaf_curve([free, hk]), ['0.5\t1\t6\t20\t0.5', '1.5\t3\t8\t10\t0.5', '3.0\t4\t6\t5\t0.25'])
rowsk = A.keff(free, '15', '0', 'x')
close('keff: k where eta_free(k) = eta_c (linear between the shells)', rowsk[0].split('\t')[1], 1.0, 1e-9)
close('keff: lambda_eff = 2 pi / k_eff', rowsk[1].split('\t')[1], 2 * 3.14159265358979, 1e-9)
same('keff: eta_eff is eta_c', rowsk[2], 'eta_eff_x\t15\t0')
same('keff: no crossing gives nan k and lambda', A.keff(free, '50', '1', 'y')[:2], ['k_eff_y\tnan\tnan', 'lambda_eff_y\tnan\tnan'])
close('eta_at_wavelength: eta at k = 2 pi / lambda', A.eta_at_wavelength(free, 2 * 3.14159265358979, 'q')[0].split('\t')[1], 15.0, 1e-9)

# ---- experiment reductions on synthetic tables
lad = tsv('ladder.tsv', 'fluid\tlambda\tdt\tT\tT_se\n'
                        'gw\t0.5\t0.01\t1.001\t0.001\ngw\t0.5\t0.02\t1.0115\t0.001\ngw\t0.5\t0.04\t1.05\t0.001\n'
                        'gw\t0.5\t0.05\t1.001\t0.001\n'
                        'md\t0.5\t0.01\t1.2\t0.001\n')
same('dt_within_1pct: the last rung within 1 % before the first outside, its uniform error',
     A.dt_within_1pct(lad), ['dt_T1pct_gw_l0.5\t0.02\t%s' % A.cfmt('%.3g', 0.02 / math.sqrt(12)), 'dt_T1pct_md_l0.5\t0\t%s' % A.cfmt('%.3g', 0.01 / math.sqrt(12))])
lad_nan = tsv('ladder_nan.tsv', 'fluid\tlambda\tdt\tT\tT_se\n'
                                'gw\t0.5\t0.01\t1.001\t0.001\ngw\t0.5\t0.02\tnan\tnan\ngw\t0.5\t0.03\t1.001\tnan\n')
same('dt_within_1pct: an unstable rung (T and stderr nan) ends the ladder, not counted within 1 %',
     A.dt_within_1pct(lad_nan), ['dt_T1pct_gw_l0.5\t0.01\t%s' % A.cfmt('%.3g', 0.01 / math.sqrt(12))])
same('largest_sigmas: the largest |value| / stderr and the count',
     A.largest_sigmas(tsv('s.tsv', 'quantity\tvalue\tstderr\nd_a1\t-3\t1\nd_a2\t1\t0\nd_a3\t2\t0.5\nother\t100\t1\n'), 'd'),
     ['largest_sigmas_d\t4\t0', 'largest_sigmas_d_cases\t2\t0'])
# a value -1.003 +- 0.002 about theory -1: |d| = 0.003, t = (0.003 + 2 x 0.002) / 1 = 0.007
tp = tsv('tp.tsv', 'quantity\tvalue\tstderr\np\t-1.003\t0.002\nq\t0.52\t0.01\n')
r = A.tolerance_to_pass(tp, 'p', '-1', 'p_tol')[0].split('\t')
same('tolerance_to_pass: the row it names', r[0], 'p_tol')
close('tolerance_to_pass: (|v - theory| + 2 se) / |theory| at a negative theory', r[1], 0.007)
close('tolerance_to_pass: its error se / |theory|', r[2], 0.002)
r = A.tolerance_to_pass(tp, 'q', '0.5', 'q_tol')[0].split('\t')
close('tolerance_to_pass: relative to theory (0.02 + 0.02) / 0.5', r[1], 0.08)
try:
    A.tolerance_to_pass(tp, 'absent', '1', 'x')
    check('tolerance_to_pass: a missing row is an error', False, 'no error')
except SystemExit as e:
    check('tolerance_to_pass: a missing row is an error naming it', 'absent' in str(e), str(e))
tol = tsv('tol.tsv', 'solver\ttolerance\teta\teta_se\terror\terror_se\titerations\tcpu_per_step\ttrue_rel_error\n'
                     'pcg\t1e-1\t1\t1\t1\t1\t1\t1\t1e-2\npcg\t1e-3\t1\t1\t1\t1\t1\t2\t1e-6\npcg\t1e-5\t1\t1\t1\t1\t1\t3\t1e-10\n')
r = A.true_error_slopes(tol)[0].split('\t')
close('true_error_slopes: log-log slope of an exact power law', r[1], 2.0, 1e-5)
close('rel_error: (e - r) / r', A.rel_error('3', '0', '2', '0')[0].split('\t')[0], 0.5)
close('rel_error: error sqrt(es^2 + (e rs / r)^2) / r', A.rel_error('3', '0.3', '2', '0.4')[0].split('\t')[1],
      math.sqrt(0.09 + 0.36) / 2, 1e-4)
prof = tsv('prof.tsv', 'pos\tdensity\tdensity_se\n0.5\t3\t0.1\n1.5\t4\t0.3\n2.5\t5\t0.4\n9.5\t1\t0.1\n')
same('bulk_density: mean over the bulk bins, errors in quadrature / n', A.bulk_density(prof, '1:3'), ['4.500000\t0.25'])
same('first_defined: the first data row', A.first_defined(prof, 2), ['3\t0.1'])
same('phi-row: count / n', A.COMMANDS['phi-row'](['phi0.1', '1', '8']), ['phi_phi0.1\t0.125\t0'])
same('pm_text: decimals fall with the size', [A.pm_text({'a': '123.456', 'b': '0.5', 'c': 'nan'}, {'a': '1.23', 'b': '0.01', 'c': 'nan'}, q)
                                              for q in 'abcd'], ['123.5 +- 1.2', '0.5000 +- 0.0100', 'none', '-'])

# a 4 x 4 density map of side 4 (bin centres 0.5 ... 3.5), the cylinder at (0.5, 0.5) with rex 1.1:
# by minimum image 5 bins lie within rex (the centre's and its 4 periodic neighbours), 11 remain
grid = 'x\ty\tdensity\tvx\tvy\n' + '\n'.join(
    ''.join('%g\t%g\t5\t0\t0\n' % (i + 0.5, j + 0.5) for i in range(4)) for j in range(4))
r = A.density_fields(tsv('map.tsv', grid), '4', '0.5', '0.5', '1.1', '4')[0].split('\t')
same('density_fields: bins outside rex by minimum image', r[2], '11')
close('density_fields: residual sqrt(sum (n - n0)^2) / nb', r[0], math.sqrt(11) / 11, 1e-9)
# |div u| of u = (1, 2, 0, 0) along x in every row, v = 0: periodic central differences over 2 dx = 2
# give 1, -0.5, -1, 0.5 (mean |div u| 0.75; differences clamped at the edges would give 0.5)
grid = 'x\ty\tdensity\tvx\tvy\n' + '\n'.join(
    ''.join('%g\t%g\t4\t%d\t0\n' % (i + 0.5, j + 0.5, (1, 2, 0, 0)[i]) for i in range(4)) for j in range(4))
r = A.density_fields(tsv('map2.tsv', grid), '4', '2', '2', '0', '4')[0].split('\t')
close('density_fields: mean |div u| by periodic central differences', r[1], 0.75, 1e-12)
# residual_floor_free: three 4 x 4 maps n = n0 + 0.1 + 0.3 w_r, the noise w_r the Walsh patterns
# (-1)^i, (-1)^j, (-1)^(i+j), orthogonal to each other and to a constant: every pair's cross sum is the
# true field's 16 x 0.01, so the residual is sqrt(0.16) / 16 = 0.025 exactly and each leave-one-out
# estimate too (jackknife error 0), while each map's plain residual carries the noise (0.0791)
walsh = (lambda i, j: (-1) ** i, lambda i, j: (-1) ** j, lambda i, j: (-1) ** (i + j))
maps = [tsv('walsh%d.tsv' % k, 'x\ty\tdensity\tvx\tvy\n' + '\n'.join(''.join(
    '%g\t%g\t%.17g\t0\t0\n' % (i + 0.5, j + 0.5, 4.1 + 0.3 * w(i, j)) for i in range(4)) for j in range(4)))
    for k, w in enumerate(walsh)]
r = A.residual_floor_free('q', '4', '2', '2', '0', '4', *maps)[0].split('\t')
close('residual_floor_free: the true field without the noise floor', r[1], 0.025, 1e-12)
close('residual_floor_free: leave-one-out estimates equal, jackknife error 0', r[2], 0.0, 1e-12)
close('residual_floor_free: the plain residual of one map carries the floor',
      A.density_fields(maps[0], '4', '2', '2', '0', '4')[0].split('\t')[0], math.sqrt(16 * 0.01 + 16 * 0.09) / 16, 1e-9)
# noise alone (no true field): the cross sums are 0, the residual 0 (a negative C would also give 0)
maps0 = [tsv('walsh0_%d.tsv' % k, 'x\ty\tdensity\tvx\tvy\n' + '\n'.join(''.join(
    '%g\t%g\t%.17g\t0\t0\n' % (i + 0.5, j + 0.5, 4 + 0.3 * w(i, j)) for i in range(4)) for j in range(4)))
    for k, w in enumerate(walsh)]
close('residual_floor_free: noise alone gives 0', A.residual_floor_free('q', '4', '2', '2', '0', '4', *maps0)[0].split('\t')[1], 0.0, 1e-12)
try:
    A.residual_floor_free('q', '4', '2', '2', '0', '4', *maps[:2])
    same('residual_floor_free: two runs refused', 'accepted', 'refused')
except SystemExit as e:
    same('residual_floor_free: two runs refused', 'jackknife needs 3' in str(e), True)

# ---- more reductions with closed-form answers
close('project: the amplitude of x along w', A.project(['2', '4', '6'], ['1', '2', '3']), 2.0)
same('project: w = 0 gives nan', A.project(['1'], ['0']), 'nan')
o = A.v_relerr(10.0, [0.03, 0.04])
close('v_relerr: relative errors in quadrature', o.se, 0.5)
r = A.bisect_dt_max('f', 'p', '1', ' 1:4 1:4')[0].split('\t')
close('bisect_dt_max: geometric middle of the bracket', r[3], 2.0)
close('bisect_dt_max: a bracket shared by every seed counts once (width / sqrt 12)', r[4], 3 / math.sqrt(12), 1e-3)
r = A.bisect_dt_max('f', 'p', '1', ' 1:4 4:16')[0].split('\t')
close('bisect_dt_max: mean over the seeds', r[3], 5.0)
close('bisect_dt_max: scatter and the brackets\' resolution in quadrature', r[4],
      math.sqrt(9 + (math.sqrt(9 + 144) / math.sqrt(12) / 2) ** 2), 1e-3)
same('bisect_dt_max: a bracket at the end of the range gives nan', A.bisect_dt_max('f', 'p', '1', ' 1:inf 1:4')[0], 'f\tp\t1\tnan\tnan\t1\tinf')
# dt_max = C x^p (1 + beta x^q) to first order: ln dt = ln C + p ln x + beta x^q exactly, equal relative errors
xs = [1e4, 2e4, 3e4, 5e4, 7e4, 1e5]
dm = tsv('dtmax.tsv', 'family\tparameter\tvalue\tdt_max\tdt_max_se\n' + ''.join(
    'a\ta\t%g\t%.17g\t%.17g\n' % (x, math.exp(0.3 - 0.5 * math.log(x) + 2 * x ** -0.5), 0.01 * math.exp(0.3 - 0.5 * math.log(x) + 2 * x ** -0.5)) for x in xs))
r = A.dt_max_corrected(dm, 'a', '1e4', '1e5', '-0.5', 'p', 'b', 'c')
close('dt_max_corrected: the exponent p of an exact corrected law', r[0].split('\t')[1], -0.5, 1e-4)
close('dt_max_corrected: the correction beta', r[1].split('\t')[1], 2.0, 1e-3)
close('dt_max_slope: a pure power law\'s exponent', A.dt_max_slope(tsv('pl.tsv', ''.join('a\ta\t%g\t%.17g\t0.001\n' % (x, 3 * x ** -0.5) for x in xs)),
                                                                      'q', 'a', '1', '1e9')[0].split('\t')[1], -0.5, 1e-4)
# paired: two seeds, each an exact corrected law with its own offset, brackets of one width
seeds = tsv('seeds.tsv', 'family\tparameter\tvalue\tseed\tdt_max\tdt_stable\tdt_unstable\n' + ''.join(
    'a\ta\t%g\t%d\t%.17g\t%.17g\t%.17g\n' % (x, sd, math.exp(c - 0.5 * math.log(x) + x ** -0.5), 0.99 * math.exp(c - 0.5 * math.log(x) + x ** -0.5),
                                             1.01 * math.exp(c - 0.5 * math.log(x) + x ** -0.5)) for sd, c in ((1, 0.1), (2, 0.4)) for x in xs))
r = A.dt_max_paired(seeds, 'a', '1e4', '1e5', '-0.5', 'p')
close('dt_max_paired: the mean exponent over the seeds (offsets cancel)', r[0].split('\t')[1], -0.5, 1e-4)
check('dt_max_paired: five rows (total, stat, pure, model, resolution)', len(r) == 5 and r[4].startswith('p_resolution'), r)
# start-up: every run's profile is A(t) y with A = 0.5, 0.8, 1, 1 at t = 1 ... 4; steady over t >= 3
blk = ''.join('block\tt\tpos\tvx\n' + ''.join('%d\t%d\t%g\t%.17g\n' % (b, b + 1, y, A_ * y) for b, A_ in enumerate((0.5, 0.8, 1.0, 1.0))
                                              for y in (0.5, 1.5)) for _ in range(3))
gd = tempfile.mkdtemp(prefix='dpd-growth-', dir=tmp)
r = A.couette_growth(blk.split('\n')[:-1], '3', 'x', gd)[0].split('\t')
close('couette_growth: t90 linear between block times', r[1], 2.5, 1e-12)
close('couette_growth: identical runs, zero jackknife error', r[2], 0.0)
same('couette_growth: a(t) written per block', open(os.path.join(gd, 'growth_x.tsv')).read(), 't\ta\n1\t0.5\n2\t0.8\n3\t1\n4\t1\n')
# equal error: iterations = -10 ln E, CPU = 2 x iterations, E* = 1e-3 between 1e-2 and 1e-4
lad = tsv('ee.tsv', 'solver\ttolerance\titerations\titerations_se\ttrue_error\tcpu_seconds\tcpu_seconds_se\n' + ''.join(
    '%s\tt\t%.17g\t0\t%g\t%.17g\t0\n' % (s, -f * 10 * math.log(e), e, -f * 20 * math.log(e)) for s, f in
    (('scheme1', 1), ('scheme2_paper', 2), ('scheme2_consistent', 1), ('pcg', 1), ('pcg_2level', 0.5)) for e in (1e-2, 1e-4, 1e-6)))
r = dict(l.split('\t', 1) for l in A.equal_error(lad, '1e-3'))
close('equal_error: iterations interpolated in log E', r['iterations_at_Estar_scheme1'].split('\t')[0], -10 * math.log(1e-3), 1e-5)
same('equal_error: the best solver', r['best_iterations_is_pcg_2level'], '1\t0')
close('equal_error: the ratio to the best', r['iteration_ratio_scheme2_best'].split('\t')[0], 4.0, 1e-5)

blk = ''.join('block\tt\tpos\tvx\n' + ''.join('%d\t%d\t%g\t%.17g\n' % (b, b + 1, y, A_ * y) for b, A_ in enumerate((0.5, 0.6, 0.7, 1.0))
                                              for y in (0.5, 1.5)) for _ in range(2))
close('couette_growth: t90 between the last two blocks (%.6g)',
      A.couette_growth(blk.split('\n')[:-1], '4', 'y', gd)[0].split('\t')[1], 3 + (0.9 - 0.7) / 0.3, 1e-6)
r = dict(l.split('\t', 1) for l in A.equal_error(lad, '3e-3'))
close('equal_error: interpolated off the midpoint in log E', r['iterations_at_Estar_scheme1'].split('\t')[0], -10 * math.log(3e-3), 1e-5)


def inverse3(m):
    """Gauss-Jordan inverse of a 3 x 3 matrix (an independent route to the fit's coefficients)"""
    a = [list(row) + [1.0 if i == j else 0.0 for j in range(3)] for i, row in enumerate(m)]
    for c in range(3):
        piv = max(range(c, 3), key=lambda r: abs(a[r][c]))
        a[c], a[piv] = a[piv], a[c]
        f = a[c][c]
        a[c] = [x / f for x in a[c]]
        for r in range(3):
            if r != c:
                g = a[r][c]
                a[r] = [x - g * y for x, y in zip(a[r], a[c])]
    return [row[3:] for row in a]


rows_ = [(1.0, math.log(x), x ** -0.5) for x in xs]
M = [[sum(r[i] * r[j] for r in rows_) for j in range(3)] for i in range(3)]
res = math.sqrt(inverse3(M)[1][1]) * math.log(1.01 / 0.99) / math.sqrt(12)
r = A.dt_max_paired(seeds, 'a', '1e4', '1e5', '-0.5', 'p')
close('dt_max_paired: the resolution sqrt(sum c_i^2 ln(hi/lo)^2 / 12), c_i = (X^T X)^-1 X^T row of p', r[4].split('\t')[1],
      float('%.3g' % res), 1e-12)

# ---- pan-2008 (each formula at a point or a limit with a closed-form answer)
same('table_rows: the rows after the header', A.table_rows(tsv('fit.tsv', 'q\tv\tse\nmu\t3.6\t0.1\nchi\t0.2\t0\textra\n')),
     ['mu\t3.6\t0.1', 'chi\t0.2\t0\textra'])
same('table_rows: a suffix on the first three columns', A.table_rows(tsv('fit2.tsv', 'q\tv\tse\nmu\t3.6\t0.1\textra\n'), '_dt0.01'),
     ['mu_dt0.01\t3.6\t0.1'])
o = A.mean_runs(['1\t0.3', '3\t0.4'])
close('mean_runs: the mean of the runs', o.v, 2.0)
close('mean_runs: error sqrt(sum se^2) / n', o.se, 0.25)
o = A.column_mean_se(tsv('cm.tsv', 'block\tdrag\ttorque\n0\t1\t9\n1\t2\t9\n2\t3\t9\n'), 2)
close('column_mean_se: mean of the column after the header', o.v, 2.0)
close('column_mean_se: sample sd / sqrt(n)', o.se, math.sqrt(1 / 3))
r = A.noise_row('n', '0.1', '100', '49').split('\t')
close('noise_row: se^2 t', r[1], 1.0)
close('noise_row: a variance\'s relative error sqrt(2 / dof)', r[2], float('%.2g' % math.sqrt(2 / 49)), 1e-12)
close('half_percent_time: the factor (se / 0.005)^2', A.half_percent_time('0.01', None, 49).split('\t')[0], 4.0)
close('half_percent_time: the time t (se / 0.005)^2', A.half_percent_time('0.01', '10', 49).split('\t')[0], 40.0)
o = A.per_unit_ratio('2', '0.1', '1', '6', '0.3', '2')
close('per_unit_ratio: (b / db) / (a / da)', o.v, 1.5)
close('per_unit_ratio: relative errors in quadrature', o.se, 1.5 * math.sqrt(0.05 ** 2 + 0.05 ** 2))
close('per_unit_ratio: a negative ratio has a positive error', A.per_unit_ratio('-2', '0.1', '1', '6', '0.3', '2').se,
      1.5 * math.sqrt(0.05 ** 2 + 0.05 ** 2))
o = A.theory_ratio('4', '0.2', '2', '0.1', '2')
close('theory_ratio: value over theory', o.v, 2.0)
close('theory_ratio: the value\'s and u\'s relative errors in quadrature', o.se, 2 * math.sqrt(0.05 ** 2 + 0.05 ** 2))
same('production_time: sum of (steps - equilibration) dt', A.production_time(['1500', '2500'], '500'), '30')
same('time_of_steps: steps dt as awk prints it', A.time_of_steps('150000'), '1500')
close('rotlet_torque: eq. 18, -8 pi mu Omega R^3', A.rotlet_torque('1', '1', '-1'), 8 * math.pi, 1e-9)
close('chain_shape_factor: N times eq. 18\'s torque gives T_s = 1',
      A.chain_shape_factor(str(4 * 8 * math.pi * 0.125), '0', '1', '0.5', '-1', '4').split('\t')[0], 1.0, 1e-9)
same('chain_positions: touching spheres centred on c', A.chain_positions('2', '0.5', '5'), '([4.5000,5.0000,5.0000],[5.5000,5.0000,5.0000])')
same('diff_sigmas: the difference and its sigmas', A.diff_sigmas(tsv('ds.tsv', 'quantity\tvalue\tstderr\nA\t5\t0.3\nB\t1\t0.4\n'), 'A', 'B', 'd'),
     ['d\t4\t0.5', 'd_sigmas\t8\t0'])
Lphi = (4 * math.pi / 3 / 0.001) ** (1 / 3)
r = A.drag_theory('1', '1', '6', str(math.pi), '%.17g' % Lphi).split()
close('drag_theory: eq. 19, u = N_f g / (6 pi mu R)', r[0], 1.0, 1e-9)
close('drag_theory: Hasimoto\'s factor at phi = 0.001', r[1], 1 - 1.7601 * 0.1 + 0.001 - 1.5593e-6, 1e-9)
close('drag_theory: phi = 4 pi R^3 / (3 L^3)', r[2], 0.001, 1e-5)
r = A.superficial_velocity('0.5', '0.001', '100', '0.01', '100000').split('\t')
close('superficial_velocity: the Ornstein-Uhlenbeck error sqrt(2 u / (N_f g T)) where it exceeds the blocks\'', r[1], float('%.4g' % math.sqrt(0.001)), 1e-12)
same('superficial_velocity: the blocks\' error where it is larger', A.superficial_velocity('0.5', '0.1', '100', '0.01', '100000').split('\t')[1], '0.1')
r = A.ou_over_blocks(tsv('sup.tsv', 'gammaC\tu\tu_se\tu_se_blocks\tu_se_ou\n3.5\t1\t0.2\t0.01\t0.02\n'))[0].split('\t')
close('ou_over_blocks: the Ornstein-Uhlenbeck error over the blocks\'', r[1], 2.0)
close('ou_over_blocks: 1 / sqrt(38) and half of u\'s relative error in quadrature', r[2], float('%.4g' % (2 * math.sqrt(1 / 38 + 0.01))), 1e-12)
tq = tsv('tq.tsv', 'gammaC\tgammaS\ttorque\ttorque_se\n0\t5.5\t2\t0.1\n3.5\t5.5\t12.5\t0.1\n7\t5.5\t23\t0.2\n0\t2.5\t100\t0.1\n')
close('torque_slope: the weighted slope at gamma^S = 5.5 (other rows left out)', A.torque_slope(tq, '-0.4')[0].split('\t')[1], 3.0, 1e-9)
close('torque_slope: scaled to Omega = -0.4 from Omega = -2', A.torque_slope(tq, '-2')[0].split('\t')[1], 0.6, 1e-9)
close('couette_torque: eq. 21, 8 pi mu R^3 (curl/2 - Omega)', A.couette_torque('1', '1', '0.5', '-0.5'), 8 * math.pi, 1e-9)
cv = tsv('cv.tsv', ''.join('%d\t%d\n' % (x, -x) for x in range(1, 6)))
r = dict(l.split('\t', 1) for l in A.control_variate(cv))
close('control_variate: D\'s intensity var(D) t, var of 1..5 = 2.5', r['cv_noise_D'].split('\t')[0], 25.0)
close('control_variate: R = -D is perfectly anticorrelated, rho = -1', r['cv_rho'].split('\t')[0], -1.0)
close('control_variate: the best c = -cov / var R = 1', r['cv_c_best'].split('\t')[0], 1.0)
close('control_variate: D + R has no noise', r['cv_noise_total'].split('\t')[0], 0.0)
s1 = tsv('cv1.tsv', 'quantity\tvalue\nother\t1\ntorque_on_s1_y\t0.5\ntorque_random_on_s1_y\t-0.1\ntorque_on_s0_x\t0.7\ntorque_random_on_s0_x\t0.2\n')
same('cv_pairs: D and R of each sphere and component, sorted', A.cv_pairs([s1]), ['0.5\t-0.1', '0.7\t0.2'])
same('bin_window: z -+ half', A.bin_window('3.0', '0.25'), '2.75:3.25')
o = A.linear_scale('0.4', '0.02', '0.05', '0.2')
close('linear_scale: v g / g0', o.v, 0.1)
close('linear_scale: the error likewise', o.se, 0.005)
F, T = (float(x) for x in A.wall_sphere_theory('1', '1', '1', '1e7').split())
close('wall_sphere_theory: far from the wall F -> 6 pi mu u R (Stokes)', F, 6 * math.pi, 1e-6)
close('wall_sphere_theory: far from the wall T h -> 8/3 pi mu u R^3', T * 1e7, 8 / 3 * math.pi, 1e-6)
F, T = (float(x) for x in A.wall_sphere_theory('1', '1', '1', '2').split())
close('wall_sphere_theory: eq. 22 at q = 1/2', F, 6 * math.pi * (1 - 0.25 / 9) / (1 - 0.3263 + 0.0395 - 0.0151250), 1e-9)
close('wall_sphere_theory: eq. 22\'s torque at q = 1/2', T, 4 / 3 * math.pi * (1 + 0.0379 + 0.01225), 1e-9)
close('no_slip_poiseuille: 3 g (z - 1)(9 - z) / (2 mu)', A.no_slip_poiseuille('2', '5', '3'), 16.0)
F, T = (float(x) for x in A.two_sphere_theory('1e7', '1', '1', '1').split())
close('two_sphere_theory: far apart F -> 6 pi mu R u', F, 6 * math.pi, 1e-6)
close('two_sphere_theory: far apart T l^2 -> 8 pi mu R^4 u 3/4', T * 1e14, 6 * math.pi, 1e-6)
same('two_sphere_positions: c and c -+ l/2', A.two_sphere_positions('12', '1.0'), '6.0000 5.5000 6.5000')
same('linear_decision: linear and resolved', A.linear_decision('1.05', '0.03'), '1')
same('linear_decision: not resolved (2 se > 0.20)', A.linear_decision('1.05', '0.11'), '0')
same('linear_decision: not linear', A.linear_decision('1.3', '0.05'), '0')
r = dict(l.split('\t', 1) for l in A.torque_projection('1', '0.3', '0.3', '1', '0.1', '1', '3600', '100'))
close('torque_projection: t = noise / (0.1 T)^2', r['projection_time_row1'].split('\t')[0], 100.0)
close('torque_projection: CPU-hours at the measured cost per time unit', r['projection_cpu_hours_row1'].split('\t')[0], 100.0)
close('torque_projection: the hours left after 600 time units', r['projection_cpu_hours_remaining_row1'].split('\t')[0], -500.0)
same('sphere_blocks: the first n mod B samples skipped, (Fa + Fb) / 2 and (Ta - Tb) / 2 per block',
     A.sphere_blocks(['%d\t%d\t%d\t0' % (9, 9, 9)] + ['%d\t%d\t%d\t%d' % (k, k, 2 * k, 0) for k in range(1, 7)], '2'),
     ['block\tdrag\ttorque', '0\t2\t2', '1\t5\t5'])
same('window_means: means of W samples, a partial window dropped', A.window_means([1.0, 2.0, 3.0, 4.0, 5.0], 2), ['1.5', '3.5'])
same('colloid_count: 0.027 L^3 rounded', A.colloid_count('10'), '27')
o = A.stokes_radius('0.5', '0.1', repr(1 / (6 * math.pi)))
close('stokes_radius: eq. 16, R = 1 / (6 pi mu D)', o.v, 2.0, 1e-12)
close('stokes_radius: D\'s relative error', o.se, 0.4, 1e-12)
r = A.box_corrected('1', '0.1', repr(2.837297 / (6 * math.pi)), '2')
close('box_corrected: D + 2.837297 / (6 pi mu L)', r[0].split('\t')[1], 1.5, 1e-9)
r = A.se_ratio_row('q', '1\t0.2', '0.1', '3').split('\t')
close('se_ratio_row: the replicas\' error over the groups\'', r[1], 2.0)
close('se_ratio_row: relative error 1 / sqrt(2 (n - 1))', r[2], 1.0)
fs = A.finite_size_fit(tsv('dl.tsv', 'L\tinv_L\tc\tD\tD_se\n' + ''.join('%d\t%.17g\t1\t%.17g\t0.01\n' % (L, 1 / L, 2 - 3 / L) for L in (4, 5, 8, 10))))
r = dict(l.split('\t', 1) for l in fs[1:])
close('finite_size_fit: the slope of an exact D = D_inf + slope / L', r['slope'].split('\t')[0], -3.0, 1e-9)
close('finite_size_fit: D_inf the intercept', r['value_at_centre'].split('\t')[0], 2.0, 1e-9)
close('finite_size_fit: r2 of an exact line', r['r2'].split('\t')[0], 1.0, 1e-9)
fs = A.finite_size_fit(tsv('dl2.tsv', 'L\tinv_L\tc\tD\tD_se\n1\t0\t1\t0\t0.1\n1\t1\t1\t1\t0.1\n1\t2\t1\t0\t0.1\nx\t3\t1\t5\tnan\n'))
r = dict(l.split('\t', 1) for l in fs[1:])
close('finite_size_fit: the slope\'s error scaled by sqrt(chi^2 / dof) above 1', r['slope'].split('\t')[1],
      float('%.4g' % (math.sqrt(0.005) * math.sqrt(200 / 3))), 1e-12)
same('finite_size_fit: a row without an error left out', r['points'], '3\t0')
same('finite_size_fit: fewer than 3 usable rows is refused', A.finite_size_fit(tsv('dl3.tsv', 'h\n1\t1\t1\t1\t0.1\n')), None)
r = dict(l.split('\t', 1) for l in A.yeh_hummer_rows(repr(2.837297 / (6 * math.pi)) + '\t0', '-2\t0.1', '0.5\t0', repr(1 / (6 * math.pi))))
close('yeh_hummer_rows: c = 2.837297 / (6 pi eta)', r['yeh_hummer_coefficient'].split('\t')[0], 1.0, 1e-9)
close('yeh_hummer_rows: -slope / c', r['finite_size_slope_over_yeh_hummer'].split('\t')[0], 2.0, 1e-9)
close('yeh_hummer_rows: R from the extrapolated D', r['R_extrapolated'].split('\t')[0], 2.0, 1e-9)
r = A.yeh_hummer_corrections(tsv('yh.tsv', 'quantity\tvalue\tstderr\nD_colloid_L6\t1\t0\n'), '24\t0', ['6'])
close('yeh_hummer_corrections: c (1/6 - 1/8)', r[0].split('\t')[1], 1.0, 1e-9)
close('yeh_hummer_corrections: D + c / L', r[1].split('\t')[1], 5.0, 1e-9)

# ---- simulation arguments
same('steps_for: t / dt rounded to the nearest', A.steps_for('10', '0.003'), '3333')
same('steps_for: rounds up from one half', A.steps_for('0.5', '0.2'), '3')
same('sample_every: the nearest stride for an interval', A.sample_every('0.05', '0.02'), '3')
same('sample_every: at least 1', A.sample_every('0.05', '0.5'), '1')
same('tcaf_axis_nmax: two past kq (4 pi / 3)^(1/3)', A.tcaf_axis_nmax('3'), '6')
same('tcaf_axis_nmax: capped at 31', A.tcaf_axis_nmax('40'), '31')
same('geometric_mid: sqrt(a b)', A.geometric_mid('0.001', '0.1', '%.4g'), '0.01')
same('octahedron_inertia: (2/3) M d^2', A.octahedron_inertia('6', '0.5'), '1')
same('octahedron_inertia: at d = 0.25', A.octahedron_inertia('3', '0.25'), '0.125')
same('sum-fmt: a + b in the format', A.COMMANDS['sum-fmt'](['%.3f', '2.0', '0.0005']), ['2.001'])

close('sigmas: (a - b) / sqrt(sa^2 + sb^2)', A.sigmas('5', '0.3', '1', '0.4'), 8.0)
close('sigmas: against an exact number', A.sigmas('3', '0.5', '2', '0'), 2.0)
same('sigmas: no error gives nan', A.sigmas('3', '0', '2', '0'), 'nan')
same('sigmas: a row, a number for B', A.COMMANDS['sigmas'](['q', '3\t0.5', '2']), ['q\t2\t0'])

# ---- exp.sh's shared helpers
pb = tsv('pb.tsv', 'block\tt\tpos\tn\tvx\n' + ''.join('%d\t0\t%g\t1\t%g\n' % (b, y, sl * y) for b, sl in ((0, 1), (1, 3)) for y in (0, 1, 2, 5))
         + '1\t0\t1.5\t1\tnan\n')
o = A.block_stat(pb, '0', '2', 'slope')
close('block_stat: the mean of the blocks\' slopes over lo <= pos <= hi', o.v, 2.0)
close('block_stat: their standard error as independent blocks', o.se, 1.0)
o = A.block_stat(pb, '0', '2', 'mean')
close('block_stat: the mean of v_x over lo < pos < hi (the bin at pos = 1 only)', o.v, 2.0)
same('block_stat: one block gives nan', A.block_stat(tsv('pb1.tsv', 'h\n0\t0\t1\t1\t2\n0\t0\t2\t1\t4\n'), '0', '3', 'slope').pair(), 'nan\tnan')
o = A.max_rel_dev(tsv('dens.tsv', '# c\npos\tdensity\tse\n0.5\t1\t0.1\n1.5\t2\t0.2\n2.5\t3\t0.3\n9.5\t100\t1\n'), '0', '3')
close('max_rel_dev: the largest |x - mean| / mean in the range (the first if tied)', o.v, 0.5)
close('max_rel_dev: that bin\'s stderr / mean', o.se, 0.05)
r = A.wall_stress(['3\t0.1', '1\t0.1', '-2\t0.1', '-2\t0.1'], '1').split()
close('wall_stress: (F_bottom - F_top) / (2 lx)', r[0], 4.0)
close('wall_stress: the errors added linearly', r[1], 0.2)
o = A.pct_from('3\t0.3', '2')
close('pct_from: 100 (a / b - 1) against an exact b', o.v, 50.0)
close('pct_from: its error 100 sa / b', o.se, 15.0)
same('pct_from: a nan operand gives nan', A.pct_from('nan\tnan', '2').pair(), 'nan\tnan')
same('minus: a - b, b exact', A.COMMANDS['minus'](['5\t0.3', '2']), ['3\t0.3'])
same('mean-se-row: one run has no error', A.COMMANDS['mean-se-row'](['q', '2.5']), ['q\t2.5\t0'])
same('mean-se-row: the runs\' mean and standard error', A.COMMANDS['mean-se-row'](['q', '1', '3']), ['q\t2\t1'])
same('lattice_tag: phi = 6 k^3 / (13500 + 6 k^3) and the side 15 kq / kp', A.lattice_tag('15', '5', '4'), 'phi0.6000 5')

# ---- methods/pan-estimators
pr = tsv('prec.tsv', 'h' + '\tc' * 13 + '\n' + 'a' + '\tx' * 11 + '\t1.5\t2\n' + 'b' + '\tx' * 11 + '\tinf\t3\n' + 'c' + '\tx' * 11 + '\t0.5\tinf\n')
same('precision_totals: the claims\' CPU-hours summed, inf left out', A.precision_totals(pr),
     ['precision_cpu_hours_at_paper_values\t2\t0', 'precision_cpu_hours_at_our_values\t5\t0'])
hp = tsv('hp.tsv', 'e' + '\tc' * 12 + '\n' + ''.join('pan-2008/%s' % e + '\tx' * 11 + '\t%s\n' % v for e, v in
                                                (('tab01-couette', '1'), ('fig02-drag', '2'), ('tab01-couette', '4'))))
same('half_percent_totals: per source (name to its first -) in the order met, and in all', A.half_percent_totals(hp),
     ['half_percent_cpu_hours_tab01\t5\t0', 'half_percent_cpu_hours_fig02\t2\t0', 'half_percent_cpu_hours_all\t7\t0'])
r = A.ladder_row('-1', '2', '0.1', '100', '4', repr(1 / (8 * math.pi)), '1').split('\t')
close('ladder_row: the torque over eq. 18 (-8 pi mu Omega R^3 = 1 here)', r[3], 2.0, 1e-9)
close('ladder_row: the noise se^2 x time', r[5], 1.0)
close('ladder_row: (se / T)^2 x CPU-hours', r[7], 0.01)
lt = tsv('lad.tsv', 'omega\tt\tse\tr\trse\tnoise\n-1.0\t2\t0.1\t1.05\t0.01\t1.4\n')
same('ladder_rows: the ratio, and the noise with sqrt(2 / 49)', A.ladder_rows(lt, '-1.0'),
     ['ladder_torque_ratio_W-1.0\t1.05\t0.01', 'ladder_noise_W-1.0\t1.4\t' + A.astr(1.4 * math.sqrt(2 / 49))])
Lp = repr((4 * math.pi / 3 / 0.001) ** (1 / 3))
r = A.hold_row(Lp, '1', '3', '0.3', '0', '0.2', '10', '1', repr(1 / (6 * math.pi)), '1', '6').split('\t')
K = 1 / (1 - 1.7601 * 0.1 + 0.001 - 1.5593e-6)
close('hold_row: zeta = drag / u over Stokes (1 here)', r[4], 3.0, 1e-9)
close('hold_row: Hasimoto\'s K at phi = 0.001', r[6], K, 1e-6)
close('hold_row: u at F_ext, F_ext / zeta', r[9], 2.0, 1e-9)
close('hold_row: the Einstein form var x T / 2', r[14], 0.2, 1e-9)
ht = tsv('hold.tsv', 'L\tu\tz\tzs\t5\t6\tK\n10\t0.3\t20\t1\t.\t.\t1.2\n6\t0.3\t30\t1.5\t.\t.\t1.5\n')
r = A.hold_ratio(ht, '6', '0.3', '10', '0.3', 'z', 'h')
close('hold_ratio: zeta over zeta', r[0].split('\t')[1], 1.5)
close('hold_ratio: relative errors in quadrature', r[0].split('\t')[2], float('%.4g' % (1.5 * math.sqrt(0.0025 + 0.0025))))
close('hold_ratio: Hasimoto\'s K over K', r[1].split('\t')[1], 1.25)
sc = tsv('sc.cfg', 'steps = 9000;\nequilibration = 500; # a comment = 7\n# equilibration = 900\n')
same('prod_time: steps less the scene\'s equilibration, times dt', A.prod_time('1500', tsv('a1', 'x.cfg\n--set\nsteps=1500\n'), sc), '10')
same('prod_time: the arguments\' equilibration first', A.prod_time('1500', tsv('a2', 'x.cfg\n--set\nequilibration=1000\n'), sc), '5')
o = A.gk_rotational_friction('3', '0.2', repr(1 / (8 * math.pi)), '1')
close('gk_rotational_friction: variance x time / 2 over 8 pi mu R^3 (1 here)', o.v, 1.5, 1e-9)

# twins: base windows alternating +-1, the driven twin base + 0.5 from the 6th window on (a response of 0.5 from t = 0.25), the
# tiny twin base + d (seed 1) and base - d (seed 2): its rms difference d over sqrt(2) x the sd of one run's
# window means over the second half
import statistics
base = [1.0 if w % 2 else -1.0 for w in range(1, 11)]
d_ = 0.8
tw = []
for sd_, sign in ((1, 1), (2, -1)):
    for name, vals in (('b', base), ('d', [v + (0.5 if w >= 6 else 0) for w, v in enumerate(base, 1)]), ('t', [v + sign * d_ for v in base])):
        tw.append(tsv('tw%d%s' % (sd_, name), ''.join('%.17g\n' % v for v in vals)))
sd_one = statistics.stdev([base[w - 1] for w in range(6, 11)] * 2)
twout = os.path.join(tmp, 'twin.tsv')
r = dict(l.split('\t', 1) for l in A.twins('k', tw, '0.5', '2', twout))
tab = [l.split('\t') for l in open(twout).read().split('\n')[1:-1]]
close('twins: the response, driven minus base', tab[1][1], 0.5)
close('twins: the tiny twin\'s rms difference over sqrt(2) x one run\'s sd', tab[0][4], float('%.4g' % (d_ / (math.sqrt(2) * sd_one))), 1e-12)
close('twins: the driven twin\'s difference about the response is 0', tab[1][5], 0.0)
same('twins: the decorrelation time, the first bin where the tiny twin reaches 0.5', r['twin_k_decorrelation_time'], '0\t0.25')
same('twins: an unbiased estimator over [0.25, 0.5]', r['twin_k_bias_0.25_0.5'].split('\t')[0], '0')

same('pair_periodic_factor: 1 / (1 - 2 x 2.837297 R / L)', A.pair_periodic_factor('2', repr(0.5 / 2.837297)), '2')
r = A.pair_box_row('12', '1.0', '0.3', '6', '0.3', '2', '1.5', '1').split('\t')
close('pair_box_row: the drag over eq. 23', r[5], 3.0)
close('pair_box_row: over the periodic prediction too', r[8], 2.0)
close('pair_box_row: Pan\'s over eq. 23', r[10], 0.5)
same('cols_where: the columns of the row matching every key', A.cols_where(tsv('cw.tsv', 'a\tb\tc\n12\tx\t0.3\n12\ty\t0.6\n'), ['1=12', '3=0.60'], ['2']), 'y')
b1 = tsv('sb1.tsv', 'block\tdrag\ttorque\n0\t1\t0.05\n1\t3\t0.15\n')
b2 = tsv('sb2.tsv', 'block\tdrag\ttorque\n0\t4\t0.2\n1\t4\t0.2\n')
r = A.torque_over_drag([b1]).split('\t')
close('torque_over_drag: one run: the torque\'s mean over the drag\'s', r[0], 0.05)
r = A.torque_over_drag([b1, b2]).split('\t')
close('torque_over_drag: runs weighted by their errors (a run without an error left out)', r[2], 2.0)
r = A.tf_ratios('0.05\t0.005\t10\t0.1', '0.04\t0.004\t8\t0.1', '1.2', '1.5')
close('tf_ratios: T/F of 8^3 over 12^3', r[0].split('\t')[1], 1.25)
close('tf_ratios: the periodic prediction\'s ratio', r[2].split('\t')[1], 0.8)
r = A.tf_torque('0.05\t0.005\t10\t0.1', '4\t0.2', '0.1')
close('tf_torque: T/F x drag', r[0].split('\t')[1], 0.2)
close('tf_torque: over eq. 23', r[1].split('\t')[1], 2.0)
r = A.pan_compare_row('x\ty', 'q', '2', '4', '3', '0.5', '-', '-').split('\t')
close('pan_compare_row: ours over Pan\'s', r[6], 1.5)
close('pan_compare_row: the difference in our stderrs', r[8], 2.0)
close('pan_compare_row: Pan\'s over his theory', r[9], 0.5)

r = A.est_row('q', 'e', 's', '2', '0.2', '3', 'ck', 'k').split('\t')
close('est_row: (se / value)^2 x CPU-hours', r[6], 0.03)
close('est_row: the CPU-hours for 1 %, r / 1e-4', r[7], 300.0)
same('run_cpu_hours: the runs\' cpu_seconds summed, scaled, in hours', A.run_cpu_hours(['cpu_seconds\t3600\t0', 'x\t5\t0', 'cpu_seconds\t1800\t0'], '2'), '3')
same('fmt: a pair gives two arguments', A.COMMANDS['fmt'](['%.2f +- %.2f', '1.234\t0.056']), ['1.23 +- 0.06'])
same('half-pair: v / 2 and se / 2', A.COMMANDS['half-pair'](['3\t0.5']), ['1.5 0.25'])
same('drive_projection: the torque linear in u', A.drive_projection('0.1', '0.01', '0.6', '5'), '0.2 0.01 5')

rc = A.run_cost(tsv('rc.cfg', 'dt = 0.01;\nequilibration = 1000; # x\n'), tsv('rcs.tsv', 'quantity\tvalue\nsteps\t5000\t0\ncpu_seconds\t100\t0\n'), '2',
                ['--set', 'equilibration=3000'])
same('run_cost: production and equilibration CPU in the ratio of their steps (the arguments\' equilibration first), and the time', rc, '80\t120\t20')
# run-costs-sum: the fold the shell made with run-cost and plus, run by run (partial sums printed and
# read back); a run of no arguments (its count 0) and one whose production time is not an integer
rc2 = tsv('rcs2.tsv', 'quantity\tvalue\nsteps\t3000\t0\ncpu_seconds\t7.77777\t0\n')
runs = [(tsv('rc.cfg', 'dt = 0.01;\nequilibration = 1000; # x\n'), tsv('rcs.tsv', 'quantity\tvalue\nsteps\t5000\t0\ncpu_seconds\t100\t0\n'), '2', ['--set', 'equilibration=3000']),
        (tsv('rc.cfg', 'dt = 0.01;\nequilibration = 1000; # x\n'), rc2, '0.3', []),
        (tsv('rc3.cfg', 'dt = 0.0033;\nequilibration = 1;\n'), rc2, '1', ['--set', 'dt=0.007'])]
fold = ['0', '0', '0']
for sc, sm, fac, args in runs:
    fold = [A.COMMANDS['plus']([x, y])[0] for x, y in zip(fold, A.run_cost(sc, sm, fac, args).split('\t'))]
flat = [x for sc, sm, fac, args in runs for x in [str(len(args)), sc, sm, fac] + args]
same('run-costs-sum: run-cost summed by plus, run by run', A.COMMANDS['run-costs-sum'](flat), [' '.join(fold)])
same('run-costs-sum: one run', A.COMMANDS['run-costs-sum'](flat[:6]), ['80 120 20'])
same('paper_band: the paper tier\'s claim row, columns by name', A.paper_band(tsv('pbands.tsv', 'quantity\ttier\tkind\tlo\thi\tpaper\nq\tpaper\tgate\t1\t2\t3\nq\tpaper\tclaim\t0\t10\t4\n'), 'q'), '0\t10\t4')
r = A.precision_row('e\tq\t0\t10\t4\t5\t1\t 100:10:50:-:1\tnote', '').split('\t')
same('precision_row: the verdict under the rule (5 +- 2 inside [0, 10])', r[7], 'PASS')
close('precision_row: the deciding stderr at the paper\'s value, half its distance to the nearer edge', r[8], 2.0)
close('precision_row: the CPU-hours, (sqrt(se^2 CPU))^2 / se_needed^2 + equilibration', r[12], float('%.4g' % ((100 / 4 + 10) / 3600)), 1e-12)
r = A.precision_row('e\tq\t-\t-\t4\t5\t1\t 100:10:50:-:1\tnote', '0.005').split('\t')
close('precision_row: Pan\'s 0.5 % of his value as the stderr to reach', r[8], 0.02)

# ---- the command line a run.sh calls (tools/analyse)
cli = os.path.join(HERE, '..', 'tools', 'analyse')
if 'ANALYSIS_PY' not in os.environ:
    p = subprocess.run([cli, 'diff', '5\t0.3', '2\t0.4'], capture_output=True, text=True)
    same('tools/analyse diff: a TSV row on stdout, exit 0', (p.stdout, p.returncode), ('3\t0.5\n', 0))
    p = subprocess.run([cli, 'no-such-subcommand'], capture_output=True, text=True)
    check('tools/analyse: an unknown subcommand exits 2 naming the subcommands, nothing on stdout',
          p.returncode == 2 and 'usage' in p.stderr and p.stdout == '', (p.returncode, p.stderr[:60]))
    p = subprocess.run([cli, 'lookup', os.path.join(tmp, 'no-such.tsv'), 'q'], capture_output=True, text=True)
    check('tools/analyse: a missing file exits 1 naming it', p.returncode == 1 and 'no-such.tsv' in p.stderr, (p.returncode, p.stderr))
    # the compiled module follows its source: an edit that keeps the file's size and modification
    # time (a mutant and its revert within one second) must not be read from a stale cache
    cp = os.path.join(tmp, 'tools')
    os.mkdir(cp)
    for f in ('analyse', 'analysis.py'):
        shutil.copy2(os.path.join(HERE, '..', 'tools', f), os.path.join(cp, f))
    first = subprocess.run([os.path.join(cp, 'analyse'), 'diff', '5\t0.3', '2\t0.4'], capture_output=True, text=True).stdout
    src = os.path.join(cp, 'analysis.py')
    st = os.stat(src)
    text = open(src).read()
    marker = 'def v_diff(a, sa, b, sb):'
    body = text.index(marker)
    minus = text.index('num(a) - num(b)', body)
    with open(src, 'w') as f:
        f.write(text[:minus] + 'num(a) + num(b)' + text[minus + len('num(a) - num(b)'):])
    os.utime(src, ns=(st.st_atime_ns, st.st_mtime_ns))
    second = subprocess.run([os.path.join(cp, 'analyse'), 'diff', '5\t0.3', '2\t0.4'], capture_output=True, text=True).stdout
    same('tools/analyse: an edit of the same size and time is not hidden by the compiled cache', (first, second), ('3\t0.5\n', '7\t0.5\n'))

# the analysis server runs calls one after another in one process (tools/analysis_server.py): a
# call must leave nothing for the next. analysis.py binds its module-level names once (functions,
# constants, the command tables), no function rebinds one (global, nonlocal), none caches, and the
# command tables are not changed after they are built
import ast
src = ast.parse(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools', 'analysis.py')).read())
rebound = sorted({type(n).__name__ for n in ast.walk(src) if isinstance(n, (ast.Global, ast.Nonlocal))})
cached = sorted({ast.unparse(d) for n in ast.walk(src) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)) for d in n.decorator_list})
top = [t.id for n in src.body if isinstance(n, (ast.Assign, ast.AnnAssign, ast.AugAssign))
       for t in (n.targets if isinstance(n, ast.Assign) else [n.target]) if isinstance(t, ast.Name)]
twice = sorted({x for x in top if top.count(x) > 1})
tables = {x for x in top if x.endswith('COMMANDS')}
# (inside functions and lambdas: the import builds the tables)
inner = [n for f in ast.walk(src) if isinstance(f, (ast.FunctionDef, ast.Lambda)) for n in ast.walk(f)]
mutated = sorted({ast.unparse(n) for n in inner if isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute)
                  and isinstance(n.func.value, ast.Name) and n.func.value.id in tables and n.func.attr in ('update', 'pop', 'setdefault', 'clear', 'popitem')}
              | {ast.unparse(t) for n in inner if isinstance(n, (ast.Assign, ast.AugAssign, ast.Delete))
                 for t in (n.targets if isinstance(n, (ast.Assign, ast.Delete)) else [n.target])
                 if isinstance(t, ast.Subscript) and isinstance(t.value, ast.Name) and t.value.id in tables})
mutable = sorted({t.id for n in src.body if isinstance(n, ast.Assign) for t in n.targets if isinstance(t, ast.Name)
                  and t.id not in tables and (isinstance(n.value, (ast.List, ast.Dict, ast.Set, ast.ListComp, ast.DictComp, ast.SetComp))
                                              or isinstance(n.value, ast.Call) and ast.unparse(n.value.func) in ('dict', 'list', 'set', 'collections.defaultdict', 'defaultdict'))})
same('analysis.py keeps no state between calls: no module-level list, dict or set but the command tables', mutable, [])
same('analysis.py keeps no state between calls: no global or nonlocal', rebound, [])
same('analysis.py keeps no state between calls: no decorated (cached) function', cached, [])
same('analysis.py keeps no state between calls: each module-level name bound once', twice, [])
same('analysis.py keeps no state between calls: the command tables not changed by a call', mutated, [])

shutil.rmtree(tmp)
print('%d passed, %d failed' % (passed, failed))
sys.exit(1 if failed else 0)
