"""The one error of a teacher's grading.yaml (no ROS): raised where a key of it is
checked (the teacher's file's reader, the term's dates), one line naming the mistake."""


class TeacherFileError(Exception):
    """One line naming the mistake in grading.yaml."""
