"""The course's template kept in a profile as fingerprints, and a class too
small to tell the course's code (grading/similarity/template_prints.py,
pairs.py, page.py; no ROS, nothing run): three submissions on the course's
template, one independent and two disguised copies of one other class's code."""
import json
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..'))
pytest.importorskip('copydetect')
import similarity_fixtures  # noqa: E402
from exp_assignment2.grading import cli  # noqa: E402
from exp_assignment2.grading.plan import profiles  # noqa: E402
from exp_assignment2.grading.similarity import template_prints  # noqa: E402


@pytest.fixture(scope='module')
def small(tmp_path_factory):
    return similarity_fixtures.make_small_class(str(tmp_path_factory.mktemp('small')))


def reported(folder, out, *options):
    assert cli.main([folder, '--similarity-only', '--out', out] + list(options)) == 0
    with open(os.path.join(out, 'similarity.json')) as f:
        data = json.load(f)
    with open(os.path.join(out, 'similarity.html')) as f:
        return data, {(p['a'], p['b']): p for p in data['pairs']}, f.read()


def a_profile(path, text='base: dog\n'):
    path.write_text('# the course of 2025, on the dog profile\n' + text)
    return str(path)


def test_a_small_class_without_a_template_gets_no_figure(small, tmp_path):
    _, folder = small
    data, found, page = reported(folder, str(tmp_path / 'out'))
    assert data['too_small'] and len(found) == 3
    assert all(p['share'] is None for p in found.values())
    assert all(s['top_with'] is None for s in data['submissions'])   # the index: no figure
    assert 'too few to tell the course' in page and '%</td>' not in page
    assert 'state_machine.py' in page       # the passages, for a person to read


def test_the_profiles_template_is_left_out_by_default(small, tmp_path):
    template, folder = small
    profile = a_profile(tmp_path / 'course.yaml')
    assert cli.main(['--fingerprint-template', profile, '--template', template]) == 0
    assert 'template_fingerprints' not in profiles.load(profile)   # never in a run's plan
    assert profiles.load(profile)['name'] == 'dog'
    data, found, page = reported(folder, str(tmp_path / 'out'), '--profile', profile)
    assert not data['too_small'] and data['template_fingerprints'] > 500
    assert found[('copy_a', 'copy_b')]['share'] >= 0.9                # the copies: a copy
    assert found[('copy_a', 'independent')]['share'] < 0.2
    assert found[('copy_b', 'independent')]['share'] < 0.2
    assert "the profile&#x27;s fingerprints of template" in page or \
        'the profile\'s fingerprints of template' in page
    with_folder = reported(folder, str(tmp_path / 'folder'), '--template', template)[1]
    assert {k: p['share'] for k, p in with_folder.items()} == \
        {k: p['share'] for k, p in found.items()}                   # as --template DIR


def test_writing_again_replaces_them_and_keeps_the_rest(small, tmp_path):
    template, _ = small
    profile = a_profile(tmp_path / 'course.yaml', 'base: dog\nname: dog_2025\nduration: 300\n')
    for _ in range(2):
        assert cli.main(['--fingerprint-template', profile, '--template', template]) == 0
    text = open(profile).read()
    assert text.startswith('# the course of 2025') and text.count(template_prints.MARK) == 1
    assert text.count('\ntemplate_fingerprints:') == 1
    assert profiles.load(profile)['duration'] == 300
    prints = template_prints.of_profile(profile)
    assert prints.folders == ['template'] and len(prints.keys) > 500
    assert 'def ' not in text and 'robot' not in text.split(template_prints.MARK)[1]


def test_fingerprints_made_otherwise_are_refused_in_one_line(small, tmp_path):
    template, _ = small
    profile = a_profile(tmp_path / 'course.yaml')
    assert cli.main(['--fingerprint-template', profile, '--template', template]) == 0
    with open(profile) as f:
        text = f.read().replace(template_prints.SCHEME, 'winnow-k20-w5-poly64.0')
    with open(profile, 'w') as f:
        f.write(text)
    with pytest.raises(profiles.ProfileError, match='write them again'):
        template_prints.of_profile(profile)
    assert cli.main(['--fingerprint-template', profile]) == 2            # no --template
    assert cli.main(['--fingerprint-template', str(tmp_path / 'nope.yaml'), '--template',
                     template]) == 2

