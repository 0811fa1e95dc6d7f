"""The grading's plan, made on the teacher's side before any run starts: the
settings (command line over grading.yaml over the profile), and for every
submission the one place its commands are decided, in this order:

1. the teacher's ``grading.yaml``: the submission's own ``commands``, then
   those for all;
2. its README, read as a person reads it (:mod:`~exp_assignment2.grading.plan.choose`);
3. the profile's default;

then the profile's ``world_commands`` before them, and ``{package}`` (the
submission's package name) and ``{sim}`` (this package's name beside it) put
in. Each submission is read from the teacher's side's one copy of it
(:mod:`~exp_assignment2.grading.entry.copies`: an archive unpacked, a
directory copied, with ``submissions.unpack``'s limits): its README, scripts
and launch files. The result is a
:class:`~exp_assignment2.grading.plan.spec.RunSpec` per run. grading.yaml is
read once (:func:`read_settings`) and the folder discovered once
(:func:`entries`) by the command line, which hands both down.
"""
import os

from exp_assignment2.grading.plan import assignment
from exp_assignment2.grading.entry import build_deps
from exp_assignment2.grading.plan import defaults
from exp_assignment2.grading.entry import deadlines
from exp_assignment2.grading.plan import episodes as episodes_
from exp_assignment2.grading.entry import git_entries
from exp_assignment2.grading.plan import launch_nodes
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.plan import ros_release
from exp_assignment2.grading.plan import starts
from exp_assignment2.grading.entry import packages as packages_
from exp_assignment2.grading.plan.choose import Context, aliases, choose
from exp_assignment2.grading.plan.commands import TeacherFileError, read_teacher_file, \
    readme_entries, readme_texts
from exp_assignment2.grading.paths import PACKAGE
from exp_assignment2.grading.record import traceback_line
from exp_assignment2.grading.plan.spec import RunSpec, settings
from exp_assignment2.grading.entry.submissions import SubmissionError, discover

OWN_NAME, SIM_PACKAGE = 'exp_assignment2', 'exp_assignment2_sim'   # see overlay/build.py


def sim_name(package):
    """This package's name in a run beside the student's ``package``."""
    return SIM_PACKAGE if package == OWN_NAME else OWN_NAME


def _put_in(command, package, sim=None):
    return command.replace('{package}', package).replace('{sim}', sim or sim_name(package))


def resolve(package_dir, package, name, teacher, profile, provided, read_launches, root=None,
            packages=None, other_parts=None):
    """{'commands', 'starts', 'build_packages', 'commands_from',
    'readme_commands', 'notes'} for one submission (see the module's
    docstring; ``starts``: when each command starts and from which folder,
    :mod:`~exp_assignment2.grading.plan.starts`; ``build_packages``: the submission's packages its
    README's build lines name). ``read_launches(requests, packages)``: the
    launch files' nodes (launch_nodes.read, or a test's). ``root``: the
    submission's folder (its README is read there first, then in
    ``package_dir``; the commands' folders are relative to it);
    ``packages``: {name: folder} of all its packages;
    ``other_parts(entries, readme_texts)``: {command: why} of the README's
    commands about another assignment (assignment.other_sections)."""
    root = root or package_dir
    own_packages = dict(packages or {package: package_dir})
    # this package's name beside the student's: exp_assignment2_sim if theirs is called so
    sim = SIM_PACKAGE if OWN_NAME in own_packages else OWN_NAME
    own = (teacher.get('submissions') or {}).get(name) or {}
    ctx = Context(package, package_dir, provided, world=bool(profile['world_commands']),
                  root=root, packages=own_packages)
    delay = float(profile.get('delay', 5))
    world = [_put_in(c, package, sim) for c in profile['world_commands']]
    listed, notes, builds = [], [], []
    if own.get('commands') or teacher.get('commands'):
        chosen = own.get('commands') or teacher['commands']
        source = 'grading.yaml (submissions: %s)' % name if own.get('commands') else \
            'grading.yaml (commands)'
        written = [_put_in(c, package, sim) if isinstance(c, str) else
                   dict(c, run=_put_in(c['run'], package, sim)) for c in chosen]
        plan = starts.typed(world, delay) + starts.from_teacher(written, delay, len(world))
        for start in plan:
            if start['cwd'] and not os.path.isdir(os.path.join(root, start['cwd'])):
                notes.append('`%s`: cwd %s is not a folder of the submission: run from its '
                             'root' % (start['command'], start['cwd']))
                start['cwd'] = ''
    else:
        entries, readme = readme_entries(root, package_dir, ctx.packages)
        others = other_parts(entries, readme_texts(root, package_dir)) \
            if other_parts and readme else {}
        skipped = set()
        for index, entry in enumerate(entries):     # another assignment's: left out, in place
            if entry['command'] in others or entry.get('of') in skipped:
                skipped.add(index)
                entry['left_out'] = others.get(entry['command']) or \
                    entries[entry['of']]['left_out']
        launch_packages = dict(ctx.packages, **{sim: PACKAGE})
        for alias, folder in aliases(entries, ctx).items():    # $(find NAME) for that name too
            launch_packages.setdefault(alias, folder)
        runs, listed = choose(entries, ctx, lambda requests: read_launches(
            requests, launch_packages))
        for entry in entries:
            builds += [p for p in entry.get('packages') or [] if p in ctx.packages]
        for item in listed:         # what differs from running every line: a note each
            if item['why'] and item['kind'] != 'build' and \
                    not item['why'].startswith('a start script: its'):
                notes.append('`%s`: %s' % (item['command'], item['why']))
        source = "the submission's %s" % readme
        if runs:
            plan = starts.from_readme(world, runs, entries, delay)
        else:
            notes.append('no roslaunch or rosrun line to run in %s: the profile\'s default'
                         % (readme or 'a README (there is none)'))
            source = "the profile's default"
            chosen, said = defaults.commands([_put_in(c, package, sim) for c in
                                              profile['default_commands']], package, package_dir)
            notes += said
            plan = starts.typed(world + chosen, delay)
    return {'commands': starts.commands_of(plan), 'starts': plan,
            'build_packages': list(dict.fromkeys(builds)),
            'commands_from': source + (" after the profile's world" if world else ''),
            'readme_commands': listed, 'notes': notes}


def _readme_packages(package_dir, names):
    """The submission's packages the README's commands name, in order."""
    named = []
    for entry in readme_entries(package_dir)[0]:
        words = entry['command'].split()
        if entry['kind'] == 'ros' and len(words) > 2 and words[1] in names:
            named.append(words[1])
    return named


def read_submission(submission, copy, teacher, profile, provided, hidden, known=None):
    """What the teacher's side knows of one submission before it runs,
    read from its ``copy`` (copies.Copy): its packages, which of them the run
    builds and why, its commands (:func:`resolve`), and what it needs from
    Debian. A submission that cannot be taken gets ``rejected`` (its
    verdict is ``not_built``, with that reason)."""
    empty = {'package': None, 'commands': [], 'commands_from': '', 'readme_commands': [],
             'notes': [], 'packages': [], 'build': [], 'debian': [], 'rejected': None}
    try:
        unpacked = copy.taken()
    except SubmissionError as exc:
        return dict(empty, rejected='the submission: %s' % exc)
    found = packages_.find(unpacked.root)
    if not found:
        return dict(empty, notes=unpacked.notes,
                    rejected='the submission: no package.xml in it (a catkin package has one)')
    names = {p.name for p in found}
    root = unpacked.root
    main = assignment.main_package(found, profile, _readme_packages(root, names) or
                                   [n for p in found for n in _readme_packages(p.path, names)])

    def read(requests, packages):
        return launch_nodes.read({'launches': requests, 'packages': packages},
                                 shown=[copy.folder], hidden=hidden)
    own = {p.name: p.path for p in found}
    result = resolve(main.path, main.name, submission.name, teacher, profile,
                     provided | set(own), read, root=root, packages=own,
                     other_parts=lambda entries, texts: assignment.other_sections(
                         texts, entries, found, main, root))
    listed, built = packages_.choose(found, main, result['starts'] or result['commands'],
                                     result.get('build_packages') or (), root=root)
    needs = build_deps.resolve(built, provided | set(own),
                               known if known is not None else build_deps.available_debian())
    release = ros_release.choose(
        profile['releases'], teacher.get('release') or profile['release'],
        ((teacher.get('submissions') or {}).get(submission.name) or {}).get('release'),
        root, unpacked.notes, fallback_robot=os.path.join(PACKAGE, 'urdf'),
        package_dir=main.path)
    result.update(package=main.name, packages=listed, rejected=None, debian=needs['debian'],
                  build=[p.rel for p in built], release=release['release'],
                  release_why=release['why'], releases_next=release['next'],
                  notes=unpacked.notes + result['notes'] + needs['notes'])
    if len(found) > 1:
        result['notes'].insert(0, '%d packages found: %s built (%s)' % (
            len(found), ', '.join(p.name for p in built),
            'the others: see Packages' if len(built) < len(found) else 'all of them'))
    return result


def commands_for(submission, copies, teacher, profile, provided, hidden, known=None):
    """:func:`read_submission` from the submission's copy in ``copies``."""
    return read_submission(submission, copies.of(submission), teacher, profile, provided,
                           hidden, known)


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
    for the command line's ``args`` (see spec.settings): grading.yaml read."""
    folder = os.path.abspath(args.submissions)
    teacher = read_teacher_file(os.path.join(folder, 'grading.yaml')
                                if os.path.isdir(folder) else None)
    chosen, whence = settings(vars(args), teacher, profiles.load)
    return teacher, chosen, whence


def entries(args, log):
    """The folder's submissions to grade, in its order (``--only``'s): the
    folder discovered, its notes logged."""
    submissions, notes = discover(args.submissions)
    for note in notes:
        log(note)
    if args.only:
        unknown = set(args.only) - {s.name for s in submissions}
        if unknown:
            raise SubmissionError('--only: no submission named %s (there are: %s)' % (
                ', '.join(sorted(unknown)), ', '.join(s.name for s in submissions)))
        submissions = [s for s in submissions if s.name in args.only]
    return submissions


def plan(args, out, version, log, read, submissions, copies):
    """([RunSpec] for every submission and repeat in the folder's order, the
    profile, {setting: where its value came from}), from what was read once:
    ``read`` (:func:`read_settings`'), ``submissions`` (:func:`entries`') and
    their ``copies`` (copies.Copies)."""
    folder = os.path.abspath(args.submissions)
    teacher, chosen, whence = read
    check_with(teacher)
    profile = chosen['profile']
    for line in deadlines.unknown_names(teacher, {s.name for s in submissions}):
        log(line)
    # hidden from every run's sandbox and launch reader: the folder, the report and the
    # class's copies (a local run is on this machine, whatever its temporary directory)
    hidden = [folder if os.path.isdir(folder) else os.path.dirname(folder), out,
              copies.scratch]
    provided = launch_nodes.provided_packages()
    known = build_deps.available_debian()
    specs = []
    for submission in submissions:
        own = (teacher.get('submissions') or {}).get(submission.name) or {}
        if own.get('skip'):
            log('%s: skipped (grading.yaml)' % submission.name)
            continue
        refused = (teacher.get('errors') or {}).get(submission.name)
        git = None      # a git repository: the commit it is graded at (git_entries.py)
        if submission.kind == 'git' and not refused:
            try:
                git = git_entries.choose(submission, teacher, getattr(args, 'deadline', None))
                log('%s: %s' % (submission.name, git_entries.summary(git)))
            except Exception as exc:    # noqa: BLE001 -- the grader's fault, for this one only
                refused = 'the grader failed while reading its git repository (a fault of ' \
                    'the grader\'s, not the student\'s): %s' % traceback_line(exc)
        try:
            found = commands_for(submission, copies, teacher, profile, provided, hidden, known)
        except Exception as exc:      # noqa: BLE001 -- the grader's fault, for this one only
            log('%s: the grader failed while reading it: %s' % (submission.name,
                                                                 traceback_line(exc)))
            found, refused = {}, refused or 'the grader failed while reading the submission ' \
                '(a fault of the grader\'s, not the student\'s): %s' % traceback_line(exc)
        mine = profiles.with_teacher_roles(profile, own.get('roles'))
        count = getattr(args, 'episodes', None) or episodes_.default_count(profile)
        for episode in episodes_.episodes(profile, count, args.seed):
            for r in range(args.repeat):
                specs.append(RunSpec(
                    name=submission.name, path=submission.path, kind=submission.kind,
                    label=episodes_.label(submission.name, episode, r, count, args.repeat),
                    seed=args.seed + episode['index'] * args.repeat + r, profile=mine,
                    duration=chosen['duration'], real_time_factor=chosen['real_time_factor'],
                    hidden=hidden, version=version, refused=refused, git=git,
                    episode=episode if count > 1 or profile.get('ball_script') else None,
                    ball_script=episodes_.ball_script(profile, episode, chosen['duration']),
                    **found))
    # what the class needs from Debian, installed once, before any run (a run's
    # sandbox never installs; a worker installs what it lacks before its run)
    build_deps.install(sorted({n for spec in specs if not spec.refused for n in spec.debian}),
                       log)
    return specs, profile, whence
