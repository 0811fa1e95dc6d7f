"""Submissions' packages and a fake launch reader for the tests of a README read
as a person reads it (test_grading_choose.py, test_grading_choose_names.py)."""

DOG = {'world_commands': [], 'default_commands': ['roslaunch {package} gazebo_world.launch']}
MIRO = {'world_commands': ['roslaunch {sim} miro_world.launch'],
        'default_commands': ['rosrun {package} state_manager.py']}


def package(tmp_path, readme, files=()):
    """A package called my_pkg with a README and files {path: text}."""
    root = tmp_path / 'my_pkg'
    root.mkdir()
    (root / 'package.xml').write_text('<package><name>my_pkg</name></package>')
    (root / 'README.md').write_text(readme)
    for rel, text in dict(files).items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return str(root)


def reader(nodes, seen=None):
    """A fake launch reader: {file name: [node names]} (absent: unreadable)."""
    def read(requests, packages):
        if seen is not None:
            seen.append((requests, packages))
        return {r['key']: {'nodes': nodes[r['file']]} if r.get('file') in nodes else
                {'error': 'XmlParseException: bad'} for r in requests}
    return read


def commands_ran(got):
    """{command: (ran, why)} of each command the README gave."""
    return {c['command']: (c['ran'], c['why']) for c in got['readme_commands']}
