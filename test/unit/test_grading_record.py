"""A run's record (exp_assignment2.grading.record): its declared fields, its one
writer (the teacher's part added beside the worker's record) and one reader."""
import json

import pytest

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


def test_a_record_refuses_a_field_it_does_not_declare(tmp_path):
    with pytest.raises(TypeError, match="unknown field 'verdcit'"):
        record.RunRecord.new('ann', 'ann', 1, verdcit='passed')
    rec = record.RunRecord.new('ann', 'ann', 1)
    for put in (lambda: rec.__setitem__('cut', []), lambda: rec.update(workers=[]),
                lambda: rec.setdefault('wokers', [])):
        with pytest.raises(TypeError):
            put()
    with pytest.raises(TypeError, match='unknown teacher field verdict'):
        record.write(str(tmp_path), teacher={'verdict': 'passed'})
    with pytest.raises(TypeError):
        record.write(str(tmp_path), {'name': 'ann', 'who': 'me'})
    assert not (tmp_path / 'run.json').exists()


def test_every_field_the_grader_writes_is_declared_once():
    names = [key for key, _ in record.FIELDS]
    assert len(names) == len(set(names)) and all(why for _, why in record.FIELDS)
    from exp_assignment2.grading.plan.spec import FIELDS as SPEC
    from exp_assignment2.grading.judge.seen import TOLD
    # what a run is asked: the spec's fields the runner copies, as the spec says them
    assert {'commands', 'commands_from', 'readme_commands', 'notes', 'packages', 'release',
            'release_why', 'duration'} <= set(SPEC) & set(names)
    assert set(TOLD) <= set(names)


def test_the_teachers_part_is_added_beside_the_workers_record(tmp_path):
    """The teacher's side adds teacher.json; run.json stays as the worker wrote it."""
    where = str(tmp_path / 'record')
    worker = record.write(where, record.RunRecord.new('ann', 'ann', 1, verdict='passed',
                                                      notes=['a note of the run']))
    written = (tmp_path / 'record' / 'run.json').read_bytes()
    back = record.write(where, teacher={'workers': ['tcp://a:1', 'tcp://b:2'],
                                        'notes': ['run again'], 'cut': ['logs/x: cut']})
    assert (tmp_path / 'record' / 'run.json').read_bytes() == written
    assert back == dict(worker, teacher={'workers': ['tcp://a:1', 'tcp://b:2'],
                                         'notes': ['run again'], 'cut': ['logs/x: cut']})
    assert record.notes(back) == ['a note of the run', 'run again']
    assert record.teacher(back, 'workers') == ['tcp://a:1', 'tcp://b:2']
    assert record.teacher(worker, 'cut') == [] and record.notes(worker) == ['a note of the run']
    # a record written whole (its teacher's part in it) goes to both files
    whole = str(tmp_path / 'whole')
    assert record.write(whole, back) == back
    assert 'teacher' not in json.loads((tmp_path / 'whole' / 'run.json').read_text())


def test_a_record_of_an_older_grader_is_read_with_its_teachers_part(tmp_path):
    """workers and cut were once among the run's own fields."""
    (tmp_path / 'run.json').write_text(json.dumps({'name': 'ann', 'label': 'ann', 'seed': 1,
                                                   'workers': ['w1'], 'cut': ['x']}))
    back = record.load(str(tmp_path))
    assert back['teacher'] == {'workers': ['w1'], 'cut': ['x']} and 'workers' not in back
    (tmp_path / 'run.json').write_text(json.dumps({'name': 'ann', 'whatever': 1}))
    assert record.load(str(tmp_path)) is None


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
