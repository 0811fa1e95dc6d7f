"""A submission's camera, read from its robot files before it runs
(plan.camera_load), and a run counted at the class's costs scaled to its
camera until its own is measured (run.admission): a class whose robots carry
the course's 800 x 800 camera at 30 Hz and this package's 320 x 240 at 15 Hz
starts a cheap run beside two dear ones. No ROS, no sandbox, no Dask scheduler."""
import pytest

distributed = pytest.importorskip('distributed')
from exp_assignment2.grading.plan import camera_load  # noqa: E402
from exp_assignment2.grading.run import dispatch  # noqa: E402
from exp_assignment2.grading.run.admission import BUSY, FIXED, LIVE_MARGIN, \
    REFERENCE_FRAMES, Admission, camera_load as load  # noqa: E402
from test_grading_admission import CostlyCluster, Progress, ran  # noqa: E402
from test_grading_stopping import runs_of  # noqa: E402
from test_grading_stopping import no_wait  # noqa: E402,F401 -- the fixture


def sensor(rate, width, height, name='camera1'):
    return ('<gazebo reference="camera_link"><sensor type="camera" name="%s">'
            '<update_rate>%s</update_rate><camera name="head"><horizontal_fov>1.39</horizontal_fov>'
            '<image><width>%s</width><height>%s</height><format>R8G8B8</format></image>'
            '</camera></sensor></gazebo>' % (name, rate, width, height))


COURSE, PACKAGE = sensor(30.0, 800, 800), sensor(15.0, 320, 240)


def test_a_camera_is_counted_in_frames_of_800_by_800_a_second():
    assert camera_load.in_text('<robot>%s</robot>' % COURSE) == [pytest.approx(30.0)]
    assert camera_load.in_text(PACKAGE) == [pytest.approx(1.8)]
    assert camera_load.in_text(sensor(10, 640, 480) + COURSE) == [pytest.approx(4.8),
                                                                 pytest.approx(30.0)]
    # another sensor's numbers are not a camera's
    assert camera_load.in_text('<sensor type="ray"><update_rate>40</update_rate>'
                               '<width>1</width><height>1</height></sensor>') == []


@pytest.mark.parametrize('rate, width', [('${rate}', 800), ('nan', 800), ('inf', 800),
                                         ('-30', 800), ('30', '0'), ('', 800)])
def test_a_camera_whose_numbers_are_not_read_is_not_counted(rate, width):
    assert camera_load.in_text(sensor(rate, width, 800)) == []


def test_a_file_of_opened_sensors_that_never_close_is_read_to_its_end():
    assert camera_load.in_text('<sensor type="camera">' * 50000) == []
    assert camera_load.in_text('<sensor ' * 100000) == []
    assert len(camera_load.in_text(PACKAGE * 2000)) == 2000


def test_the_robot_files_of_the_packages_built_say_the_most(tmp_path):
    (tmp_path / 'pkg' / 'urdf').mkdir(parents=True)
    (tmp_path / 'pkg' / 'urdf' / 'robot.gazebo').write_text(PACKAGE)
    (tmp_path / 'pkg' / 'urdf' / 'head.xacro').write_text(sensor(30, 400, 400))
    (tmp_path / 'pkg' / 'notes.txt').write_text(COURSE)          # not a robot file
    (tmp_path / 'pkg' / '.git').mkdir()
    (tmp_path / 'pkg' / '.git' / 'old.urdf').write_text(COURSE)  # hidden: not read
    (tmp_path / 'other').mkdir()
    (tmp_path / 'other' / 'robot.urdf').write_text(COURSE)       # a package not built
    assert camera_load.frames(str(tmp_path), ['pkg']) == pytest.approx(7.5)
    assert camera_load.frames(str(tmp_path), ['pkg', 'other']) == pytest.approx(30.0)
    assert camera_load.frames(str(tmp_path), ['missing']) is None


def test_an_unmeasured_run_counts_the_runs_of_a_camera_alike_else_the_class_scaled():
    admission = Admission(2, 0.76, 8)
    admission.expect_frames('course', REFERENCE_FRAMES)
    admission.expect_frames('package', 1.8)
    for wrong in (float('nan'), float('inf'), -1.0, 'thirty', None):
        admission.expect_frames('unknown', wrong)              # a camera not read: as before
    small = FIXED + (1 - FIXED) * 1.8 / REFERENCE_FRAMES
    assert load(REFERENCE_FRAMES) == pytest.approx(1.0) and load(1.8) == pytest.approx(small)
    # nothing measured: the profile's figure, for the course's camera
    assert admission.per_run('course') == pytest.approx(0.76)
    assert admission.per_run('package') == pytest.approx(0.76 * small)
    assert admission.per_run('unknown') == pytest.approx(0.76)
    # a course run measured at 0.6: no camera alike for the package's, scaled from it
    admission.counted(ran(0.6), 'course')
    assert admission.per_run('package') == pytest.approx(0.6 * small)
    assert admission.per_run('other') == pytest.approx(0.6)    # no camera read: the median
    # a package run measured at 0.15: each camera at what its like measured
    admission.counted(ran(0.15), 'package')
    for name, frames, expected in (('package2', 1.8, 0.15), ('small', 2.5, 0.15),
                                   ('course2', REFERENCE_FRAMES, 0.6),
                                   ('middle', 10.0, 0.15 * load(10) / small)):
        admission.expect_frames(name, frames)
        assert admission.per_run(name) == pytest.approx(expected), name
    # a busy loop on a small camera: the loop's core on top of what its like measured
    admission.expect_frames('spins', 1.8)
    admission.expect_busy('spins')
    assert admission.per_run('spins') == pytest.approx(max(0.15, 0.76 * small) + BUSY)


def test_a_running_run_s_pace_counts_for_the_others_scaled_to_their_cameras():
    admission = Admission(2, 0.76, 8)
    admission.expect_frames('course', REFERENCE_FRAMES)
    admission.expect_frames('package', 1.8)
    admission.started('course-run', 1.0, 'course')
    admission.pace('course-run', 0.6)
    assert admission.per_run('package') == pytest.approx(0.6 * LIVE_MARGIN * load(1.8))


def test_a_cheap_camera_s_run_starts_beside_two_dear_ones(tmp_path, no_wait):
    """The profile says 0.76 a run (the course's camera): two course runs fill 1.52 of
    1.9 cores; a run of this package's camera, counted at 0.30, starts beside them
    (counted at the median, 0.76, it waited for one of them to end)."""
    names = ['a_course', 'b_course', 'c_package', 'd_course']
    facts = {'a_course': [ran(0.6)], 'b_course': [ran(0.6)], 'c_package': [ran(0.15)],
             'd_course': [ran(0.6)]}
    cluster = CostlyCluster(facts)
    admission = Admission(2, 0.76, 8)
    for name in names:
        admission.expect_frames(name, 1.8 if 'package' in name else 30.0)
    dispatch.grade(runs_of(tmp_path, names), cluster, Progress(cluster), copies=None,
                   admission=admission)
    assert ['a_course', 'b_course', 'c_package'] in cluster.at_once
    assert not any(len(group) > 3 or group.count('d_course') and 'a_course' in group
                   and 'b_course' in group for group in cluster.at_once)


def test_each_submission_built_is_read_once_from_the_teacher_s_copy(tmp_path):
    from types import SimpleNamespace
    for name, text in (('course', COURSE), ('package', PACKAGE), ('none', '<robot/>')):
        (tmp_path / name / 'urdf').mkdir(parents=True)
        (tmp_path / name / 'urdf' / 'robot.gazebo').write_text(text)

    def run(name, build=('.',), refused=None):
        return SimpleNamespace(submission=name, spec=SimpleNamespace(
            name=name, build=list(build), refused=refused, rejected=None))

    class Copies(object):
        read = []

        def of(self, submission):
            self.read.append(submission)
            return SimpleNamespace(taken=lambda: SimpleNamespace(root=str(tmp_path / submission)))
    copies = Copies()
    runs = [run('course'), run('course'), run('package'), run('none'),
            run('unbuilt', build=()), run('refused', refused='grading.yaml says so')]
    assert camera_load.of_runs(runs, copies) == {'course': pytest.approx(30.0),
                                                 'package': pytest.approx(1.8)}
    assert sorted(copies.read) == ['course', 'none', 'package']
