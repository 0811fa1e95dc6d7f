"""A run's record (exp_assignment2.grading.record): its one writer and one reader."""
import json

from exp_assignment2.grading import record


def test_a_record_round_trips(tmp_path):
    rec = record.RunRecord.new('ann', 'ann-r2', 2, verdict='timed_out', duration=60.0,
                               ended_by='wall_limit', reason='12 of 60 simulated s',
                               build={'rc': 0, 'error': None},
                               died=[{'node': 'dog-5', 'code': -6, 'exit': '-6 (SIGABRT)'}])
    written = record.write(str(tmp_path / 'runs' / 'ann-r2' / 'record'), rec)
    back = record.load(str(tmp_path / 'runs' / 'ann-r2' / 'record'))
    assert isinstance(back, record.RunRecord) and back == written == rec
    assert (back['duration'], back['ended_by']) == (60.0, 'wall_limit')
    assert json.loads(rec.to_json()) == dict(rec)
    assert not (tmp_path / 'runs' / 'ann-r2' / 'record' / 'run.json.tmp').exists()


def test_every_run_read_and_a_broken_one_left_out(tmp_path):
    runs = tmp_path / 'runs'
    record.write(str(runs / 'b' / 'record'), {'name': 'b', 'label': 'b', 'seed': 1})
    record.write(str(runs / 'a' / 'record'), {'name': 'a', 'label': 'a', 'seed': 1})
    (runs / 'c' / 'record').mkdir(parents=True)
    (runs / 'c' / 'record' / 'run.json').write_text('{not json')
    (runs / 'd').mkdir()
    assert [r['label'] for r in record.load_all(str(runs))] == ['a', 'b']
    assert record.load_all(str(tmp_path / 'none')) == []


def test_the_build_error_travels_as_data(tmp_path):
    """The driver's built event carries the build's first error as file, line and
    message (BuildFailed's), for the record and the verdict, not parsed out of a log."""
    import os
    import sys
    from exp_assignment2.grading import paths
    from exp_assignment2.original_env.overlay.build import BuildFailed, build
    here = os.path.dirname(paths.INSIDE)
    sys.path.insert(0, here)      # as the sandbox runs it: a script of its own
    try:
        import inside
    finally:
        sys.path.remove(here)
    assert inside.build_error(BuildFailed('the build of /w failed: /w/src/a.cpp:3: expected '
                                          "';' (full log: x)", '/w/src/a.cpp:3',
                                          "expected ';'")) == {
        'file': '/w/src/a.cpp', 'line': 3, 'message': "expected ';'"}
    assert inside.build_error(BuildFailed('no workspace')) == {
        'file': None, 'line': None, 'message': 'no workspace'}
    package = tmp_path / 'bad'
    package.mkdir()
    (package / 'package.xml').write_text('<package><name>x</name></package>')
    try:
        build(str(package), workspace=str(tmp_path), root=str(tmp_path / 'overlays'))
    except BuildFailed as exc:
        error = inside.build_error(exc)
    assert error['file'] == os.path.join(str(package), 'package.xml') and error['line'] is None
    assert error['message'] == 'The manifest must contain exactly one "version" tag'
