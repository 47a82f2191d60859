"""bench/run's time-to-equal-error fit and results schema, without candela or Mitsuba: the script
is loaded as a module (it has no .py extension, and importing it does not run main)."""
import copy
import glob
import importlib.machinery
import importlib.util
import json
import os
import random
import shutil
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BENCH_RUN = os.path.join(REPO, 'bench', 'run')
RESULTS = sorted(glob.glob(os.path.join(REPO, 'bench', 'results', '*.json')))


def load_bench_run(name='bench_run'):
    loader = importlib.machinery.SourceFileLoader(name, BENCH_RUN)
    spec = importlib.util.spec_from_loader(name, loader)
    module = importlib.util.module_from_spec(spec)
    dont_write = sys.dont_write_bytecode
    sys.dont_write_bytecode = True  # no bench/__pycache__
    try:
        loader.exec_module(module)
    finally:
        sys.dont_write_bytecode = dont_write
    return module


@pytest.fixture(scope='module')
def br():
    return load_bench_run()


def relative_error(x, y):
    return abs(x - y) / abs(y)


def exact_points(c, levels, floor=0.0):
    return [(s, floor + c / s) for s in levels]


def make_tte(mitsuba_points, candela_points, sec_per_spp_mi, sec_per_spp_ca):
    def side(points, sps):
        return {'points': [{'spp': s, 'relmse': e} for s, e in points], 'seconds_per_spp': sps}
    return {'candela': side(candela_points, sec_per_spp_ca), 'mitsuba': side(mitsuba_points, sec_per_spp_mi)}


# ---------------------------------------------------------------- import

def test_importing_does_not_run_main(monkeypatch):
    # main() would exit (argparse error) on this command line if the import ran it.
    monkeypatch.setattr(sys, 'argv', ['bench/run', '--no-such-flag'])
    module = load_bench_run('bench_run_import_check')
    assert callable(module.main)
    assert module.REPO == REPO


# ---------------------------------------------------------------- pure helpers

def test_get_follows_dotted_keys(br):
    d = {'a': {'b': {'c': 3}}, 'n': None}
    assert br.get(d, 'a.b.c') == 3
    assert br.get(d, 'a.b') == {'c': 3}
    assert br.get(d, 'a.x.c') is None
    assert br.get(d, 'n.c') is None
    assert br.get({'rays.camera': 1}, 'rays.camera') is None  # dots always mean nesting


def test_median_of_skips_missing_values(br):
    runs = [{'t': 3.0, 'r': {'c': 1}}, {'t': None, 'r': {'c': 50}}, {'t': 1.0, 'r': {'c': 2}},
            {'t': 90.0, 'r': {'c': 4}}, {'r': {'c': 5}}]
    assert br.median_of(runs, 't') == 3.0  # not the mean: one slow run does not move it
    assert br.median_of(runs[:4], 'r.c') == 3.0  # even count: the mean of the middle two
    assert br.median_of(runs, 'absent') is None
    assert br.median_of([], 't') is None


# ---------------------------------------------------------------- the fit

def test_fit_through_origin_exact(br):
    xs = [1 / 4, 1 / 16, 1 / 64]
    assert relative_error(br.fit_through_origin(xs, [0.37 * x for x in xs]), 0.37) < 1e-12


@pytest.mark.parametrize('c_mi,c_ca,ref_spp,levels', [
    (0.744, 0.356, 512, [4, 16, 64]),
    (0.7, 0.3, 128, [4, 16]),
    (2.5, 9.0, 512, [1, 2, 8, 32, 128]),
    (1e-3, 4e-3, 4096, [16, 64]),
])
def test_exact_points_recover_c(br, c_mi, c_ca, ref_spp, levels):
    """Points generated exactly from the model: Mitsuba c (1/spp + 1/ref_spp), candela a + c/spp
    with a = c_Mitsuba / ref_spp; the fit returns a and both c to rounding."""
    a = c_mi / ref_spp
    mitsuba = [(s, c_mi * (1 / s + 1 / ref_spp)) for s in levels]
    candela = exact_points(c_ca, levels, floor=a)
    floor, fit_mi, fit_ca = br.fit_errors(mitsuba, candela, ref_spp)
    assert relative_error(fit_mi, c_mi) < 1e-9
    assert relative_error(fit_ca, c_ca) < 1e-9
    assert relative_error(floor, a) < 1e-9


def test_ignoring_the_floor_would_be_caught(br):
    """The exact-recovery check is sharp: fitting candela's points without removing the
    reference's floor a gives a c off by far more than 1e-9."""
    c_mi, c_ca, ref_spp, levels = 0.744, 0.356, 512, [4, 16, 64]
    candela = exact_points(c_ca, levels, floor=c_mi / ref_spp)
    naive = br.fit_through_origin([1 / s for s, _ in candela], [e for _, e in candela])
    assert relative_error(naive, c_ca) > 1e-3


def test_finish_time_to_error_exact(br):
    c_mi, c_ca, ref_spp, levels = 0.744, 0.356, 512, [4, 16, 64]
    sps_mi, sps_ca = 0.045625, 0.13396
    tte = make_tte([(s, c_mi * (1 / s + 1 / ref_spp)) for s in levels],
                   exact_points(c_ca, levels, floor=c_mi / ref_spp), sps_mi, sps_ca)
    br.finish_time_to_error(tte, ref_spp)
    target = c_ca / max(levels)
    assert relative_error(tte['target_relmse'], target) < 1e-9
    assert relative_error(tte['floor_a'], c_mi / ref_spp) < 1e-9
    assert relative_error(tte['candela']['seconds'], max(levels) * sps_ca) < 1e-9
    assert relative_error(tte['mitsuba']['seconds'], c_mi / target * sps_mi) < 1e-9
    assert relative_error(tte['ratio'], (c_ca * sps_ca) / (c_mi * sps_mi)) < 1e-9


def test_time_ratio_does_not_depend_on_target(br):
    c_mi, c_ca, sps_mi, sps_ca = 0.744, 0.356, 0.045625, 0.13396
    expected = (c_ca * sps_ca) / (c_mi * sps_mi)
    for target in (1e-6, 3.3e-4, 0.0055, 0.1, 2.0):
        ratio = br.seconds_to_error(c_ca, target, sps_ca) / br.seconds_to_error(c_mi, target, sps_mi)
        assert relative_error(ratio, expected) < 1e-12
    # The seconds themselves do scale with 1/target.
    assert relative_error(br.seconds_to_error(c_ca, 1e-3, sps_ca),
                          10 * br.seconds_to_error(c_ca, 1e-2, sps_ca)) < 1e-12


def test_time_ratio_same_whatever_the_top_level(br):
    """finish_time_to_error's target is candela's error at the top spp level: other levels give
    another target and other seconds, but the same ratio."""
    c_mi, c_ca, ref_spp, sps_mi, sps_ca = 0.7, 0.3, 512, 0.05, 0.12
    results = []
    for levels in ([4, 16], [4, 16, 64], [2, 8, 32, 256]):
        tte = make_tte([(s, c_mi * (1 / s + 1 / ref_spp)) for s in levels],
                       exact_points(c_ca, levels, floor=c_mi / ref_spp), sps_mi, sps_ca)
        br.finish_time_to_error(tte, ref_spp)
        results.append(tte)
    targets = [t['target_relmse'] for t in results]
    assert len({round(t, 12) for t in targets}) == 3
    for t in results[1:]:
        assert relative_error(t['ratio'], results[0]['ratio']) < 1e-9


def noisy(points, rng, delta):
    return [(s, e * (1 + rng.uniform(-delta, delta))) for s, e in points]


@pytest.mark.parametrize('seed', range(50))
def test_noisy_points_recover_c_within_derived_bound(br, seed):
    """Each relMSE off by a factor 1 + eps, |eps| <= delta. With relative residuals,
    c_fit / c = sum(u) / sum(u^2), u_i = 1 / (1 + rho_i), which lies between 1 + min(rho) and
    1 + max(rho). Mitsuba: rho = eps, so |c_fit / c - 1| <= delta, and the floor a is off by the
    same factor. candela (after subtracting the fitted floor): rho_i = eps_i + (a s_i / c)(eps_i - eta)
    with |eta| <= delta, so |c_fit / c - 1| <= delta (1 + 2 a s_max / c)."""
    rng = random.Random(seed)
    delta = 0.05
    c_mi, c_ca, ref_spp, levels = rng.uniform(0.2, 2), rng.uniform(0.2, 2), 512, [4, 16, 64]
    a = c_mi / ref_spp
    mitsuba = noisy([(s, c_mi * (1 / s + 1 / ref_spp)) for s in levels], rng, delta)
    candela = noisy(exact_points(c_ca, levels, floor=a), rng, delta)
    floor, fit_mi, fit_ca = br.fit_errors(mitsuba, candela, ref_spp)
    slack = 1e-12
    assert relative_error(fit_mi, c_mi) <= delta + slack
    assert relative_error(floor, a) <= delta + slack
    assert relative_error(fit_ca, c_ca) <= delta * (1 + 2 * a * max(levels) / c_ca) + slack


def test_noise_bound_is_attained(br):
    """All points high by exactly 1 + delta: the fit is high by exactly 1 + delta (the bound above
    is tight, so it is no loose tolerance)."""
    delta, c, levels = 0.05, 0.5, [4, 16, 64]
    xs = [1 / s for s in levels]
    fit = br.fit_through_origin(xs, [c * x * (1 + delta) for x in xs])
    assert relative_error(fit, c * (1 + delta)) < 1e-12


def own_reference_tte(c_mi, c_ca, bias, ref_spp, levels, sps_mi, sps_ca):
    """A run in which candela has its own reference: its points against that reference
    c (1/spp + 1/ref_spp), against Mitsuba's reference a + bias + c/spp, and the two references
    `bias` apart beyond their noise."""
    a = c_mi / ref_spp
    tte = make_tte([(s, c_mi * (1 / s + 1 / ref_spp)) for s in levels],
                   [(s, c_ca * (1 / s + 1 / ref_spp)) for s in levels], sps_mi, sps_ca)
    for p in tte['candela']['points']:
        p['relmse_against_mitsuba'] = a + bias + c_ca / p['spp']
    for who in ('candela', 'mitsuba'):
        for p in tte[who]['points']:  # the schema's other keys, which the fit does not read
            p.update(relmse_blocks=p['relmse'] / 64, mean_ratio=[1.0, 1.0, 1.0], render_seconds=None)
    tte['candela_reference'] = {'spp': ref_spp, 'seconds': 1.0}
    tte['converged_difference'] = {'relmse': bias + (c_ca + c_mi) / ref_spp}
    return tte


@pytest.mark.parametrize('bias', [0.0, 4e-4, 2e-3])
def test_own_reference_separates_noise_from_a_converged_difference(br, bias):
    """Against its own reference candela's c is its noise alone, whatever the converged images'
    difference; that difference is reported as the excess, and judged against Mitsuba's image
    the ratio grows with it (and equals the own-reference ratio where there is none)."""
    c_mi, c_ca, ref_spp, levels, sps_mi, sps_ca = 0.62, 0.06, 512, [4, 16, 64], 0.044, 0.17
    tte = own_reference_tte(c_mi, c_ca, bias, ref_spp, levels, sps_mi, sps_ca)
    br.finish_time_to_error(tte, ref_spp)
    assert relative_error(tte['candela']['c'], c_ca) < 1e-9
    assert relative_error(tte['ratio'], (c_ca * sps_ca) / (c_mi * sps_mi)) < 1e-9
    diff = tte['converged_difference']
    assert abs(diff['excess'] - bias) < 1e-12
    assert relative_error(diff['noise'], (c_ca + c_mi) / ref_spp) < 1e-9
    foreign = tte['ratio_against_mitsuba_reference']
    if bias == 0.0:
        assert relative_error(foreign, tte['ratio']) < 1e-9
    else:
        # The difference does not fall with spp, so the fit takes it for a larger c.
        inflated = br.fit_through_origin([1 / s for s in levels], [c_ca / s + bias for s in levels])
        assert relative_error(foreign, tte['ratio'] * inflated / c_ca) < 1e-9
        assert foreign > tte['ratio']


def test_own_reference_run_validates_and_shows_both_ratios(br, committed):
    res = copy.deepcopy(committed)
    sc = res['scenes']['cat']
    old = sc['time_to_error']
    tte = own_reference_tte(0.62, 0.06, 2e-3, res['ref_spp'], res['levels'],
                            old['mitsuba']['seconds_per_spp'], old['candela']['seconds_per_spp'])
    tte['reference'] = old['reference']
    br.finish_time_to_error(tte, res['ref_spp'])
    sc['time_to_error'] = tte
    br.validate_results(res)
    lines = br.markdown(res).splitlines()
    header = next(line for line in lines if line.startswith('| scene | spp | candela Msamples/s'))
    def row(scene):
        spp = res['scenes'][scene]['mitsuba']['spp']
        return [c.strip() for c in next(line for line in lines
                                        if line.startswith(f'| {scene} | {spp} |')).split('|')]
    cells = row('cat')
    names = [c.strip() for c in header.split('|')]
    assert cells[names.index('time ratio')] == f"**{br.fmt(tte['ratio'])}**"
    assert (cells[names.index("time ratio, against Mitsuba's image")]
            == br.fmt(tte['ratio_against_mitsuba_reference']))
    assert cells[names.index('converged difference (relMSE)')] == br.fmt(2e-3)
    # An older run measured against Mitsuba's image only: that column repeats its one ratio.
    old_row = row('default')
    assert old_row[names.index("time ratio, against Mitsuba's image")] == br.fmt(
        res['scenes']['default']['time_to_error']['ratio'])
    assert old_row[names.index('converged difference (relMSE)')] == '–'


def test_error_not_falling_with_spp_fails_the_fit(br):
    """candela's relMSE below the reference's floor (no 1/spp decay left): c <= 0, an error."""
    c_mi, ref_spp, levels = 0.7, 128, [4, 16]
    tte = make_tte([(s, c_mi * (1 / s + 1 / ref_spp)) for s in levels],
                   [(s, 0.5 * c_mi / ref_spp) for s in levels], 0.05, 0.1)
    with pytest.raises(RuntimeError, match='error fit failed'):
        br.finish_time_to_error(tte, ref_spp)


@pytest.mark.parametrize('path', RESULTS, ids=os.path.basename)
def test_refit_reproduces_committed_figures(br, path):
    """--report refits every run: on the committed results it gives back their figures."""
    with open(path) as f:
        res = json.load(f)
    fitted = 0
    for entry in res['scenes'].values():
        stored = entry.get('time_to_error')
        if not stored or 'error' in stored:
            continue
        tte = {who: {'points': copy.deepcopy(stored[who]['points']),
                     'seconds_per_spp': stored[who]['seconds_per_spp']} for who in ('candela', 'mitsuba')}
        if 'candela_reference' in stored:  # the measured inputs of a run with candela's reference
            tte['candela_reference'] = stored['candela_reference']
            tte['converged_difference'] = {'relmse': stored['converged_difference']['relmse']}
        br.finish_time_to_error(tte, res['ref_spp'])
        keys = ['floor_a', 'target_relmse', 'ratio']
        if 'candela_reference' in stored:
            keys.append('ratio_against_mitsuba_reference')
            for key in ('noise', 'excess'):
                assert tte['converged_difference'][key] == pytest.approx(
                    stored['converged_difference'][key], rel=1e-12)
        for key in keys:
            assert tte[key] == pytest.approx(stored[key], rel=1e-12)
        for who in ('candela', 'mitsuba'):
            for key in ('c', 'seconds'):
                assert tte[who][key] == pytest.approx(stored[who][key], rel=1e-12)
        fitted += 1
    # A run may skip every scene's fit (the scale scene's 8.5 M triangles), but then says why.
    reasons = [e['time_to_error']['error'] for e in res['scenes'].values()
               if 'error' in e.get('time_to_error', {})]
    assert fitted > 0 or len(reasons) == len(res['scenes'])


# ---------------------------------------------------------------- the results schema

@pytest.fixture(scope='module')
def committed(br):
    """The newest committed run with the default and cat scenes and the seed table, which the tests
    below edit (a run of other scenes alone, e.g. --scenes cornell,lamp,sky, has none of them)."""
    assert RESULTS, 'no bench/results/*.json'
    for path in reversed(RESULTS):
        with open(path) as f:
            res = json.load(f)
        if {'default', 'cat'} <= set(res['scenes']) and 'seed_table' in res:
            return res
    pytest.fail('no bench/results/*.json with the default and cat scenes and the seed table')


@pytest.mark.parametrize('path', RESULTS, ids=os.path.basename)
def test_committed_results_validate(br, path):
    res = br.load_results(path)
    assert br.validate_results(res) is res


def delete(res, dotted):
    res = copy.deepcopy(res)
    *parents, last = dotted.split('.')
    d = res
    for p in parents:
        d = d[p]
    del d[last]
    return res


@pytest.mark.parametrize('key', ['scenes', 'date', 'ref_spp', 'machine.cpu', 'machine.load_after',
                                 'scenes.default.cpu', 'scenes.default.cpu.median',
                                 'scenes.default.scene_file',
                                 'scenes.default.time_to_error.candela.points',
                                 'scenes.default.time_to_error.ratio',
                                 'scenes.default.mitsuba.samples_per_second',
                                 'seed_table.runs_brute'])
def test_missing_required_key_is_named(br, committed, key):
    with pytest.raises(ValueError, match=f"missing key '{key}'"):
        br.validate_results(delete(committed, key))


@pytest.mark.parametrize('key,value', [('runs', '3'), ('runs', True), ('dirty', 1), ('levels', [4, '16']),
                                       ('argv', 'bench/run'), ('machine.cores', 2.0),
                                       ('scenes.default.cpu.triangles', 4.5),
                                       ('scenes.default.time_to_error.target_relmse', None),
                                       ('skipped.cat', 7), ('scenes.default', [])])
def test_mistyped_key_is_named(br, committed, key, value):
    res = copy.deepcopy(committed)
    *parents, last = key.split('.')
    d = res
    for p in parents:
        d = d[p]
    d[last] = value
    with pytest.raises(ValueError, match=key.replace('.', r'\.')):
        br.validate_results(res)


@pytest.mark.parametrize('key', ['seed_table', 'commit_given', 'scenes.default.mitsuba',
                                 'scenes.default.time_to_error'])
def test_optional_keys_may_be_absent(br, committed, key):
    br.validate_results(delete(committed, key))


def test_failed_steps_are_error_objects(br, committed):
    res = copy.deepcopy(committed)
    res['scenes']['default']['time_to_error'] = {'error': 'skipped: more than 1,000,000 triangles'}
    res['scenes']['cat']['mitsuba'] = {'error': 'mitsuba_ref.py failed (1)'}
    res['skipped']['dragon'] = 'meshes absent: x.obj'
    br.validate_results(res)
    res['scenes']['default']['time_to_error'] = {'error': 5}
    with pytest.raises(ValueError, match=r"scenes\.default\.time_to_error\.error"):
        br.validate_results(res)


def test_schema_errors_are_value_errors(br):
    assert issubclass(br.ResultsSchemaError, ValueError)
    with pytest.raises(ValueError, match='expected an object'):
        br.validate_results([])


def test_load_results_names_file_and_key(br, committed, tmp_path):
    path = tmp_path / 'bad.json'
    path.write_text(json.dumps(delete(committed, 'machine.cuda')))
    with pytest.raises(ValueError, match=r"bad\.json: results: missing key 'machine\.cuda'"):
        br.load_results(str(path))


def test_save_results_round_trip_and_invalid_still_written(br, committed, tmp_path):
    good = tmp_path / 'good.json'
    br.save_results(committed, str(good))
    assert json.loads(good.read_text()) == committed
    bad = tmp_path / 'bad.json'
    with pytest.raises(ValueError, match="missing key 'total_seconds'"):
        br.save_results(delete(committed, 'total_seconds'), str(bad))
    assert 'total_seconds' not in json.loads(bad.read_text())  # the measurements are kept


# ---------------------------------------------------------------- --report, end to end

def report_sandbox(tmp_path, res):
    """bench/run and one results file in a scratch tree (REPO is the script's parent's parent, so
    nothing in this repository is rewritten)."""
    (tmp_path / 'bench').mkdir()
    script = tmp_path / 'bench' / 'run'
    shutil.copy(BENCH_RUN, script)
    path = tmp_path / 'results.json'
    path.write_text(json.dumps(res, indent=1))
    return script, path


def test_report_prints_the_table(br, committed, tmp_path):
    script, path = report_sandbox(tmp_path, committed)
    r = subprocess.run([sys.executable, str(script), '--report', str(path), '--no-docs'],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout == br.markdown(committed) + '\n'
    assert json.loads(path.read_text()) == committed
    assert not (tmp_path / 'docs').exists()


def test_report_rejects_invalid_results(committed, tmp_path):
    script, path = report_sandbox(tmp_path, delete(committed, 'scenes.cat.cpu.rays_per_second_by_type'))
    before = path.read_text()
    r = subprocess.run([sys.executable, str(script), '--report', str(path), '--no-docs'],
                       capture_output=True, text=True)
    assert r.returncode != 0
    assert "missing key 'scenes.cat.cpu.rays_per_second_by_type'" in r.stderr
    assert 'Traceback' not in r.stderr
    assert path.read_text() == before  # left as it was


# ---------------------------------------------------------------- emitter scenes (issue 17)

def test_generated_torus_is_closed_and_wound_outwards(br):
    text = br.torus_obj(6, 1.2, 16, 8)
    verts = [tuple(map(float, l.split()[1:])) for l in text.splitlines() if l.startswith('v ')]
    tris = [tuple(int(x) - 1 for x in l.split()[1:]) for l in text.splitlines() if l.startswith('f ')]
    assert len(tris) == 2 * 16 * 8
    edges = {}
    for t in tris:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            edges[(a, b)] = edges.get((a, b), 0) + 1
    # closed and consistently wound: every directed edge once, and its reverse once
    assert all(n == 1 and edges.get((b, a)) == 1 for (a, b), n in edges.items())
    # counter-clockwise seen from outside: each face normal points away from the tube's axis circle
    for t in tris:
        p = [verts[i] for i in t]
        u = [p[1][k] - p[0][k] for k in range(3)]
        v = [p[2][k] - p[0][k] for k in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        c = [sum(q[k] for q in p) / 3 for k in range(3)]
        r = (c[0] ** 2 + c[2] ** 2) ** 0.5
        axis = [6 * c[0] / r, 0.0, 6 * c[2] / r]
        assert sum(n[k] * (c[k] - axis[k]) for k in range(3)) > 0


def test_emitter_templates_need_no_assets(br, tmp_path):
    env = {'REPO': br.REPO, 'ASSETS': str(tmp_path / 'no-assets')}
    for name in br.EMITTER_SCENES:
        scene = br.load_template(os.path.join(br.REPO, 'bench', 'scenes', name + '.json'), env)
        br.prepare_files(scene, str(tmp_path))
        assert scene['render']['max_depth'] == 5 and scene['camera']['width'] == 512
        for f in br.mesh_files(scene) + ([br.environment_map(scene)] if br.environment_map(scene) else []):
            assert os.path.isabs(f) and os.path.exists(f), f
    lamp = br.load_template(os.path.join(br.REPO, 'bench', 'scenes', 'lamp.json'), env)
    assert lamp['lights'] == []  # the base's point light is dropped
    assert br.environment_map(br.load_template(os.path.join(br.REPO, 'bench', 'scenes', 'sky.json'), env))


def test_partial_run_rewrites_only_its_docs_block(br, committed, tmp_path):
    docs = tmp_path / 'performance.md'
    docs.write_text(f'# Performance\n\n{br.BEGIN}\nmesh table\n{br.END}\n')
    emitters = copy.deepcopy(committed)
    emitters['scenes'] = {'cornell': emitters['scenes']['default']}
    emitters['skipped'] = {}
    del emitters['seed_table']
    for md, begin, end, heading in br.docs_blocks(emitters):
        br.write_docs(md, str(docs), begin, end, heading)
    text = docs.read_text()
    assert f'{br.BEGIN}\nmesh table\n{br.END}' in text
    assert '## Emitter scenes (issue 17)' in text and '| cornell | cpu, bvh |' in text
    assert [b for _, b, _, _ in br.docs_blocks(committed)] == [br.BEGIN]


def test_engines_are_rows_of_their_own_and_the_own_bvh_time_ratio_follows_samples_per_second(br, committed):
    res = copy.deepcopy(committed)
    res['scenes'] = {'cornell': res['scenes']['default']}
    sc = res['scenes']['cornell']
    for run in sc['cpu']['all_runs']:
        run['engine'] = 'embree'
    sc['cpu-bvh'] = copy.deepcopy(sc['cpu'])
    for run in sc['cpu-bvh']['all_runs']:
        run['engine'] = 'bvh'
    sc['cpu-bvh']['median']['samples_per_second'] = sc['cpu']['median']['samples_per_second'] / 2
    br.validate_results(res)
    text = br.markdown(res)
    assert '| cornell | cpu, embree |' in text and '| cornell | cpu, bvh |' in text
    assert 'time ratio, own BVH |' in text
    ratio = sc['time_to_error']['ratio']
    lines = text.splitlines()
    header = next(line for line in lines if 'time ratio, own BVH |' in line)
    row = next(line for line in lines if line.startswith(f"| cornell | {sc['cpu']['spp']} |"))
    column = [c.strip() for c in header.split('|')].index('time ratio, own BVH')
    assert [c.strip() for c in row.split('|')][column] == br.fmt(ratio * 2)
