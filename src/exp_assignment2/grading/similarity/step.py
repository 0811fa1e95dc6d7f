"""The similarity step of ``grade`` (issue 42): every submission of the folder
read from the teacher's side's copy of it (entry.copies: archives unpacked
with ``submissions.unpack``'s limits, a git repository exported at the commit
graded), its graded packages fingerprinted
(:mod:`~exp_assignment2.grading.similarity.graded`), compared with each other
and with earlier years' (``--reference``), and the report written. Runs after
the grading's runs, before its report (whose index shows each one's highest
pair), or alone (``--similarity-only``: no build, no run, no sandbox: nothing
of a student's is executed, only read).
"""
import os

from exp_assignment2.grading.entry import git_entries
from exp_assignment2.grading.plan.commands import TeacherFileError
from exp_assignment2.grading.entry.submissions import Submission, discover
from exp_assignment2.grading.similarity import fingerprints as similarity
from exp_assignment2.grading.similarity import graded
from exp_assignment2.grading.similarity import page as similarity_report
from exp_assignment2.grading.similarity import pairs


def templates_of(args, teacher, folder):
    """The template folders: ``--template`` (repeatable) over grading.yaml's
    ``template:`` (a list, relative to the submissions folder)."""
    given = list(args.template or [])
    if not given:
        listed = teacher.get('template') or []
        if isinstance(listed, str):
            listed = [listed]
        given = [os.path.join(folder, str(p)) for p in listed]
    out = [os.path.abspath(p) for p in given]
    for path in out:
        if not os.path.exists(path):
            raise TeacherFileError('template %s: no such folder or archive' % path)
    return out


def references_of(args):
    """The reference folders (``--reference``, repeatable): earlier years' submissions."""
    out = [os.path.abspath(p) for p in getattr(args, 'reference', None) or []]
    for path in out:
        if not os.path.isdir(path):
            raise TeacherFileError('--reference %s: no such folder of submissions' % path)
    return out


class Reader(object):
    """Reads submissions into fingerprints from their ``copies`` (entry.copies.Copies,
    the grading's own). ``settings``: {'teacher', 'profile', 'deadline',
    'runs_dir'}, or None: every code file counts, git repositories at their
    checked-out commit."""

    def __init__(self, copies, settings=None):
        self.copies, self.settings = copies, settings or {}
        self.built = graded.from_records(self.settings['runs_dir']) \
            if self.settings.get('runs_dir') else {}
        self.planner = None     # made when a submission's records do not say (graded.Planner)

    def read(self, submission, name=None, reference=False, whole=False):
        """A similarity.Submission of ``submission`` (as ``name``): an earlier
        year's (``reference``), or every code file of it (``whole``: a template)."""
        name = name or submission.name
        ours = not (reference or whole)
        if submission.kind == 'git' and submission.commit is None and submission.why is None:
            # not chosen by a planning (--similarity-only, a reference): the commit
            # graded, another year's its checked-out one; then copied once, as it
            git_entries.choose(submission, (self.settings.get('teacher') or {}) if ours else {},
                               self.settings.get('deadline') if ours else None)
        copy = self.copies.of(submission)
        # one that does not unpack: what came out of it
        root = copy.unpacked.root if copy.unpacked is not None else copy.dest
        folders = None
        if ours and submission.name in self.built:
            folders = self.built[submission.name]
        elif self.settings.get('profile') and not whole:
            if self.planner is None:
                self.planner = graded.Planner(self.settings.get('teacher'),
                                              self.settings['profile'])
            folders = self.planner.folders(submission.name, root)
        return similarity.Submission.read(name, root, folders, reference)


def _kind(path):
    return 'dir' if os.path.isdir(path) else ('zip' if path.endswith('.zip') else 'tar')


def _entries(submissions, skip=(), only=None):
    return [s for s in submissions if os.path.abspath(s.path) not in skip
            and s.kind != 'other' and (not only or s.name in only)]


def run(submissions, out, templates, copies, base_share=0.1, only=None, log=print,
        references=(), settings=None):
    """Compare the folder's ``submissions`` (discovered once, by the grading),
    and each with the ``references`` folders' submissions (each discovered
    once here), all read from their ``copies`` (entry.copies.Copies), the
    ``templates`` and the profile's template fingerprints (``settings``'
    ``template_prints``) left out; write the report into ``out``; the Result."""
    reader = Reader(copies, settings)
    read = [reader.read(s) for s in _entries(submissions, set(templates), only)]
    olds, names = [], set()
    for where in references:
        label = os.path.basename(where.rstrip('/')) or 'reference'
        while label in names:
            label += '_'
        names.add(label)
        olds += [reader.read(s, '%s/%s' % (label, s.name), True)
                 for s in _entries(discover(where)[0])]
    keys, named = template_keys(reader, templates)
    prints = (settings or {}).get('template_prints')     # the profile's (template_prints)
    if prints is not None:
        keys, named = keys | prints.keys, named + [prints.label()]
    limit = similarity.default_base_limit(len(read), base_share)
    result = pairs.compare(read, keys, limit, olds)
    similarity_report.write(out, result, named, references)
    top = result.pairs[0] if result.pairs else None
    log('similarity: %d submissions%s, %d pairs share code beyond %d template and %d base '
        'fingerprints%s; %s (not a verdict)' % (
            len(read), ' and %d references' % len(olds) if olds else '', len(result.pairs),
            len(keys), len(result.base), similarity_report.TOO_SMALL_LOG if result.too_small
            else '; most: %s and %s, %.0f%%%s' % (top.a, top.b, 100 * top.share,
                                                 ' (identical)' if top.identical else '')
            if top else '', os.path.join(out, 'similarity.html')))
    return result


def template_keys(reader, templates):
    """(the fingerprints' keys of the template folders or archives, each read
    whole by ``reader``; their paths)."""
    keys = set()
    for number, path in enumerate(templates):
        keys |= similarity.template_keys(reader.read(
            Submission('template_%d' % number, path, _kind(path)), whole=True).hashes())
    return keys, list(templates)
