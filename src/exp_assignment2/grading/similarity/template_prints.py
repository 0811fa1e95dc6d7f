"""The course's template kept in a profile as fingerprints (no ROS): a class
of any size has its template left out of every share, with no template
folder at hand and no code of it in the package.

``grade --fingerprint-template PROFILE.yaml --template DIR [--template DIR]``
fingerprints the template folders' code (as every submission's is read,
:mod:`.fingerprints`) and writes their keys into the profile file, replacing
those it held, as the key ``template_fingerprints``::

    template_fingerprints:
      scheme: winnow-k25-w6-poly64.1   # how they were made: others are refused
      folders: [assignment2_start]
      count: 4000
      keys: [AAAB..., ...]             # base64 of the sorted keys, 4 bytes each

A grading with the profile leaves them out of every pair's share, beside any
``--template`` given (:func:`of_profile`). The keys are hashes of 25-token
passages: nothing of the code can be read back from them. The profile's runs
never see them (``profiles.load`` leaves them out of the profile a run gets).
"""
import base64
import os
import struct

import yaml

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.similarity.fingerprints import SCHEME

KEY = profiles.TEMPLATE_PRINTS
LINE = 76                   # base64 characters a line of ``keys``
MARK = '# written by grade --fingerprint-template: hashes of the template\'s code, no code'


class TemplatePrints(object):
    """A profile's template fingerprints: ``keys`` (a set of ints) and the
    template ``folders`` they were made of (names only)."""

    def __init__(self, keys, folders):
        self.keys, self.folders = set(keys), list(folders)

    def label(self):
        return 'the profile\'s fingerprints of %s' % (', '.join(self.folders) or 'a template')


def encode(keys, folders):
    """The profile's mapping of ``keys`` made of the template ``folders``."""
    packed = base64.b64encode(struct.pack('>%dI' % len(keys), *sorted(keys))).decode('ascii')
    return {'scheme': SCHEME, 'folders': [os.path.basename(os.path.normpath(f)) for f in folders],
            'count': len(keys), 'keys': [packed[i:i + LINE] for i in range(0, len(packed), LINE)]}


def decode(value, where):
    """TemplatePrints of a profile's mapping (ProfileError: not one, or made otherwise)."""
    if not isinstance(value, dict) or not isinstance(value.get('keys'), list):
        raise profiles.ProfileError('%s: %s: a mapping with keys: written by grade '
                                    '--fingerprint-template' % (where, KEY))
    if value.get('scheme') != SCHEME:
        raise profiles.ProfileError(
            '%s: %s: made as %s, and the similarity report fingerprints as %s: write them '
            'again (grade --fingerprint-template %s --template DIR)' % (
                where, KEY, value.get('scheme'), SCHEME, where))
    try:
        packed = base64.b64decode(''.join(str(line) for line in value['keys']), validate=True)
        keys = struct.unpack('>%dI' % (len(packed) // 4), packed)
    except (ValueError, struct.error) as exc:
        raise profiles.ProfileError('%s: %s: keys: %s' % (where, KEY, exc))
    if len(packed) % 4 or len(keys) != value.get('count'):
        raise profiles.ProfileError('%s: %s: keys do not hold its count' % (where, KEY))
    return TemplatePrints(keys, [str(f) for f in value.get('folders') or []])


def of_profile(source):
    """The TemplatePrints the profile ``source`` (a name or a file) carries, or None."""
    if source is None:
        return None
    value = profiles.template_fingerprints(source)
    return None if value is None else decode(value, source)


def write_into(path, keys, folders):
    """``path`` (a profile file) with ``keys`` made of ``folders`` as its
    template fingerprints, those it held replaced; the rest of its text kept.
    The file must load as a profile before and after (ProfileError)."""
    profiles.load(path)
    with open(path) as f:
        lines = f.read().splitlines()
    kept, skipping = [], False
    for line in lines:      # the key's block, and the comment that marks it
        if line.startswith(KEY + ':'):
            skipping = True
            if kept and kept[-1] == MARK:
                kept.pop()
            continue
        if skipping and (not line.strip() or line[:1] in ' \t'):
            continue
        skipping = False
        kept.append(line)
    while kept and not kept[-1].strip():
        kept.pop()
    block = yaml.safe_dump({KEY: encode(keys, folders)}, default_flow_style=False,
                           sort_keys=False, width=LINE + 10)
    text = '\n'.join(kept + ['', MARK, block.rstrip('\n')]) + '\n'
    # beside it, as a profile file: its base: (a file) is found from there
    temporary = os.path.join(os.path.dirname(os.path.abspath(path)),
                             '.%s.writing.yaml' % os.path.basename(path))
    with open(temporary, 'w') as f:
        f.write(text)
    try:
        profiles.load(temporary)
        decode(yaml.safe_load(text)[KEY], path)
    except profiles.ProfileError:
        os.remove(temporary)
        raise
    os.replace(temporary, path)

