"""The grading's plan, made on the teacher's side before any run starts: the
settings (command line over grading.yaml over the profile), and for every
submission the one place its commands are decided, in this order:

1. the teacher's ``grading.yaml``: the submission's own ``commands``, then
   those for all;
2. its README, read as a person reads it (:mod:`.choose`);
3. the profile's default;

then the profile's ``world_commands`` before them, and ``{package}`` (the
submission's package name) and ``{sim}`` (this package's name beside it) put
in. Archives are unpacked into a scratch directory here (with
``submissions.unpack``'s limits) to read their README, scripts and launch
files; a directory is copied the same way. The result is a
:class:`~exp_assignment2.grading.spec.RunSpec` per run.
"""
import os
import shutil
import tempfile

from exp_assignment2.grading import launch_nodes, profiles
from exp_assignment2.grading.choose import Context, choose, own_has
from exp_assignment2.grading.commands import TeacherFileError, read_teacher_file, \
    readme_entries
from exp_assignment2.grading.paths import REPO
from exp_assignment2.grading.spec import RunSpec, settings
from exp_assignment2.grading.submissions import SubmissionError, discover, package_name, \
    unpack

OWN_NAME, SIM_PACKAGE = 'exp_assignment2', 'exp_assignment2_sim'   # see overlay/build.py


def sim_name(package):
    """This package's name in a run beside the student's ``package``."""
    return SIM_PACKAGE if package == OWN_NAME else OWN_NAME


def _put_in(command, package):
    return command.replace('{package}', package).replace('{sim}', sim_name(package))


def resolve(package_dir, package, name, teacher, profile, provided, read_launches):
    """{'commands', 'commands_from', 'readme_commands', 'notes'} for one
    submission (see the module's docstring). ``read_launches(requests,
    packages)``: the launch files' nodes (launch_nodes.read, or a test's)."""
    own = (teacher.get('submissions') or {}).get(name) or {}
    listed, notes = [], []
    if own.get('commands'):
        commands, source = own['commands'], 'grading.yaml (submissions: %s)' % name
    elif teacher.get('commands'):
        commands, source = teacher['commands'], 'grading.yaml (commands)'
    else:
        entries, readme = readme_entries(package_dir)
        ctx = Context(package, package_dir, provided, world=bool(profile['world_commands']))
        packages = {package: package_dir, sim_name(package): REPO}
        for entry in entries:       # $(find NAME) for the name the README gives it too
            words = entry['command'].split()
            if entry['kind'] == 'ros' and len(words) > 2 and words[1] not in provided \
                    and own_has(ctx, words):
                packages.setdefault(words[1], package_dir)
        commands, listed = choose(entries, ctx, lambda requests: read_launches(
            requests, packages))
        for item in listed:         # what differs from running every line: a note each
            if item['why'] and not item['why'].startswith('a start script: its'):
                notes.append('`%s`: %s' % (item['command'], item['why']))
        source = "the submission's %s" % readme
        if not commands:
            notes.append('no roslaunch or rosrun line to run in %s: the profile\'s default'
                         % (readme or 'a README (there is none)'))
            commands, source = profile['default_commands'], "the profile's default"
    world = [_put_in(c, package) for c in profile['world_commands']]
    return {'commands': world + [_put_in(c, package) for c in commands],
            'commands_from': source + (" after the profile's world" if world else ''),
            'readme_commands': listed, 'notes': notes}


def commands_for(submission, teacher, profile, provided, hidden):
    """``resolve`` for a submission of the folder, read from a scratch copy;
    one that does not unpack gets no commands (its run says why)."""
    scratch = tempfile.mkdtemp(prefix='exp2-readme-')
    try:
        try:
            package_dir = unpack(submission, os.path.join(scratch, 'src'))
        except SubmissionError as exc:
            return {'package': None, 'commands': [], 'commands_from': '',
                    'readme_commands': [], 'notes': ['not read: %s' % exc]}
        package = package_name(package_dir)

        def read(requests, packages):
            return launch_nodes.read({'launches': requests, 'packages': packages},
                                     shown=[scratch], hidden=hidden)
        found = resolve(package_dir, package, submission.name, teacher, profile, provided,
                        read)
        found['package'] = package
        return found
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def check_with(teacher):
    """grading.yaml's ``with:`` (the course's packages built beside each
    submission) is refused with one line: the original-code environment can
    build them (``original-env --with``), but a run's sandbox and its worker
    get the submission alone, so they would be silently missing."""
    if teacher.get('with'):
        raise TeacherFileError(
            'grading.yaml: with: is not supported: a run gets its submission alone, so the '
            "course's packages would be missing; put what the submissions need in each, or "
            'grade by hand with: bash tools/run original-env --package DIR --with DIR')


def read_settings(args):
    """(grading.yaml's settings, the settings chosen, where each came from)
    for the command line's ``args`` (see spec.settings)."""
    folder = os.path.abspath(args.submissions)
    teacher = read_teacher_file(os.path.join(folder, 'grading.yaml')
                                if os.path.isdir(folder) else None)
    chosen, whence = settings(vars(args), teacher, profiles.load)
    return teacher, chosen, whence


def plan(args, out, version, log):
    """([RunSpec] for every submission and repeat in the folder's order, the
    profile, {setting: where its value came from})."""
    submissions, notes = discover(args.submissions)
    for note in notes:
        log(note)
    folder = os.path.abspath(args.submissions)
    teacher, chosen, whence = read_settings(args)
    check_with(teacher)
    profile = chosen['profile']
    if args.only:
        unknown = set(args.only) - {s.name for s in submissions}
        if unknown:
            raise SubmissionError('--only: no submission named %s (there are: %s)' % (
                ', '.join(sorted(unknown)), ', '.join(s.name for s in submissions)))
        submissions = [s for s in submissions if s.name in args.only]
    hidden = [folder if os.path.isdir(folder) else os.path.dirname(folder), out]
    provided = launch_nodes.provided_packages()
    specs = []
    for submission in submissions:
        own = (teacher.get('submissions') or {}).get(submission.name) or {}
        if own.get('skip'):
            log('%s: skipped (grading.yaml)' % submission.name)
            continue
        found = commands_for(submission, teacher, profile, provided, hidden)
        mine = profiles.with_teacher_roles(profile, own.get('roles'))
        for r in range(args.repeat):
            specs.append(RunSpec(
                name=submission.name, path=submission.path, kind=submission.kind,
                label=submission.name if args.repeat == 1 else '%s-r%d' % (submission.name,
                                                                             r + 1),
                seed=args.seed + r, profile=mine, duration=chosen['duration'],
                real_time_factor=chosen['real_time_factor'], hidden=hidden, version=version,
                refused=(teacher.get('errors') or {}).get(submission.name), **found))
    return specs, profile, whence
