"""The similarity step of ``grade`` (issue 42): every submission of the folder
read from the teacher's side's copy of it (plan.copies: archives unpacked
with ``submissions.unpack``'s limits), fingerprinted, compared, and the
report written. Runs after the grading's runs, before its report (whose
index shows each one's highest pair), or alone (``--similarity-only``: no
build, no run, no sandbox: nothing of a student's is executed, only read).
"""
import os

from exp_assignment2.grading.similarity import fingerprints as similarity
from exp_assignment2.grading.similarity import page as similarity_report
from exp_assignment2.grading.plan.commands import TeacherFileError
from exp_assignment2.grading.plan.submissions import Submission


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


def _read(name, submission, copies):
    """A similarity.Submission from the copy of a folder or archive in ``copies``."""
    copy = copies.of(submission)
    # one that does not unpack: what came out of it
    root = copy.unpacked.root if copy.unpacked is not None else copy.dest
    return similarity.Submission.read(name, root)


def _kind(path):
    return 'dir' if os.path.isdir(path) else ('zip' if path.endswith('.zip') else 'tar')


def run(submissions, out, templates, copies, base_share=0.1, only=None, log=print):
    """Compare the folder's ``submissions`` (discovered once, by the grading),
    read from their ``copies`` (plan.copies.Copies); write the report into
    ``out``; the Result."""
    skip = set(templates)
    submissions = [s for s in submissions if os.path.abspath(s.path) not in skip
                   and s.kind != 'other' and (not only or s.name in only)]
    read = [_read(s.name, s, copies) for s in submissions]
    template_hashes = set()
    for number, path in enumerate(templates):
        name = 'template_%d' % number
        template_hashes |= _read(name, Submission(name, path, _kind(path)), copies).hashes()
    limit = similarity.default_base_limit(len(read), base_share)
    result = similarity.compare(read, template_hashes, limit)
    similarity_report.write(out, result, templates)
    top = result.pairs[0] if result.pairs else None
    log('similarity: %d submissions, %d pairs share code beyond %d template and %d base '
        'fingerprints%s; %s (not a verdict)' % (
            len(read), len(result.pairs), len(template_hashes), len(result.base),
            '; most: %s and %s, %.0f%%' % (top[2], top[3], 100 * top[0]) if top else '',
            os.path.join(out, 'similarity.html')))
    return result
