"""Which of a submission's packages its similarity is measured on: those
graded (no ROS, nothing run).

A repository that carries the next assignment with vendored public packages
(an exploration package, a mapping one) shares them with every other that
does: nobody's copying. Only the packages a run builds count: after a
grading, those its runs' records say were built (``packages``); without runs
(``--similarity-only``, a reference), as the plan decides
(:mod:`~exp_assignment2.grading.entry.packages`): the package the run is about,
those its commands start (grading.yaml's, else the README's, else the
profile's), those the README builds, and every package of the submission they
use. Launch files are not read in a sandbox here: a command the README offers
as an alternative counts too.
"""
from exp_assignment2.grading import record
from exp_assignment2.grading.plan import assignment
from exp_assignment2.grading.plan import launch_nodes
from exp_assignment2.grading.entry import packages as packages_
from exp_assignment2.grading.plan import planning


def from_records(runs_dir):
    """{submission name: [folders of the packages its runs built]} (relative
    to its root) from a grading's records; a submission none built: absent."""
    out = {}
    for run in record.load_all(runs_dir):
        built = [p['rel'] for p in run.get('packages') or [] if p.get('built')]
        if built:
            out.setdefault(run['name'], [])
            out[run['name']] += [rel for rel in built if rel not in out[run['name']]]
    return out


class Planner(object):
    """The folders of the packages graded of a submission's files, as the plan
    decides them (``teacher``: grading.yaml's settings; ``profile``)."""

    def __init__(self, teacher, profile):
        self.teacher, self.profile = teacher or {}, profile
        self.provided = launch_nodes.provided_packages()

    def folders(self, name, root):
        """[folders relative to ``root``], or None (no package: every file counts)."""
        found = packages_.find(root)
        if not found:
            return None
        names = {p.name for p in found}
        readme = planning._readme_packages(root, names) or \
            [n for p in found for n in planning._readme_packages(p.path, names)]
        main = assignment.main_package(found, self.profile, readme)
        own = {p.name: p.path for p in found}
        resolved = planning.resolve(
            main.path, main.name, name, self.teacher, self.profile, self.provided | set(own),
            lambda requests, packages: {}, root=root, packages=own,
            other_parts=lambda entries, texts: assignment.other_sections(texts, entries, found,
                                                                         main, root))
        built = packages_.choose(found, main, resolved['starts'] or resolved['commands'],
                                 resolved.get('build_packages') or (), root=root)[1]
        return [p.rel for p in built]
