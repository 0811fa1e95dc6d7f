"""The teacher's side's one copy of each submission (no ROS).

A grading reads what a student handed in on the teacher's machine for three
things: the planning (its README, packages and launch files), the archive a
worker gets (:func:`~exp_assignment2.grading.run.tasks.pack_submission`) and
the similarity report. Each submission is put in a scratch directory once
(``submissions.unpack``'s limits: links out of it left out, an archive
unpacked, a git repository's chosen commit exported: its commit is chosen
first, by the planning, or by the similarity step alone), the first time one
of them asks, and all three read that copy; it is removed with the grading's
:class:`Copies`. The worker's run directory gets its own (another machine,
maybe).
"""
import os
import shutil

from exp_assignment2.grading import scratch as grader_scratch
from exp_assignment2.grading.entry.submissions import SubmissionError, unpack


class Copy(object):
    """One submission's copy: ``folder`` (its own, shown alone to a launch
    file's reader), ``dest`` (the files, in ``folder/src``), and either
    ``unpacked`` (an :class:`~exp_assignment2.grading.entry.unpacking.Unpacked`:
    its root and notes) or ``error`` (the SubmissionError: it cannot be taken;
    ``dest`` holds what was unpacked before it)."""

    def __init__(self, folder):
        self.folder, self.dest = folder, os.path.join(folder, 'src')
        self.unpacked = self.error = None

    def taken(self):
        """The Unpacked; its SubmissionError raised when it cannot be taken."""
        if self.error is not None:
            raise self.error
        return self.unpacked


class Copies(object):
    """Every submission's :class:`Copy` for one grading, in a scratch directory
    removed by :meth:`close` (or at the end of a ``with``)."""

    def __init__(self, scratch_root=None):
        self.scratch = grader_scratch.make('teacher', scratch_root)
        self._made = {}       # the submission's path -> its Copy

    def of(self, submission):
        """The submission's Copy, made the first time it is asked for."""
        key = os.path.abspath(submission.path)
        if key not in self._made:
            copy = Copy(os.path.join(self.scratch, str(len(self._made))))
            try:
                copy.unpacked = unpack(submission, copy.dest)
            except SubmissionError as exc:
                copy.error = exc
            self._made[key] = copy
        return self._made[key]

    def close(self):
        shutil.rmtree(self.scratch, ignore_errors=True)
        self._made = {}

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
