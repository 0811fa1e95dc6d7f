"""The pictures of a run's windows, both ends (no ROS, no X).

In the sandbox, :mod:`~exp_assignment2.grading.run.display` captures the student's top-level
windows and :class:`CaptureBook` decides what is kept of them: a picture of a window when it
changed, at most once per ``period`` wall s, within a run's limits (windows, pictures, bytes); past
the pictures or the bytes it thins what it has (every second picture of each window) and doubles
the period, so the whole run stays covered. It writes ``display/windows.json`` (titles, pictures
with their wall time, what the limits cost) and the pictures beside it.

For the report, :func:`shown_at` says which picture each window showed at
moments of simulated time, by the truth server's pairs of (simulated s, wall
s) in ``record/clock.jsonl``. Titles are the student's text: the page
escapes them; file names are only taken as this module writes them.
"""
import json
import os
import re

INDEX = 'windows.json'
MAX_WINDOWS = 8            # titles captured in a run; later ones only counted
MAX_PICTURES = 400         # pictures kept in a run, all windows together
MAX_BYTES = 24 * 2 ** 20   # bytes of pictures kept in a run
MAX_SIDE = 1600            # px: a larger window's picture is scaled down to fit
MAX_READ = 2048            # px: of a larger window, its top-left part is read
MAX_TITLE = 200            # characters of a title kept
MAX_LOOK = 256             # top-level windows looked at, each period
LEFT_OUT_NAMED = 20        # titles of left-out windows named on the page
MAX_LEFT_OUT_SEEN = 10000  # titles of left-out windows told apart (counted once each)
PICTURE = re.compile(r'^w\d{1,3}_\d{1,7}\.jpg$')
UNTITLED = '(untitled)'


def clean_title(title):
    if isinstance(title, bytes):
        title = title.decode('utf-8', errors='replace')
    title = ''.join(c if c.isprintable() else ' ' for c in str(title or '')).strip()
    return title[:MAX_TITLE] or UNTITLED


class CaptureBook(object):
    """What is kept of a run's windows, in ``directory`` (see the module)."""

    def __init__(self, directory, period=1.0, max_windows=MAX_WINDOWS,
                 max_pictures=MAX_PICTURES, max_bytes=MAX_BYTES):
        self.directory, self.period = directory, float(period)
        self.max_windows, self.max_pictures, self.max_bytes = max_windows, max_pictures, max_bytes
        self.windows = []             # [{'title', 'pictures': [{file, wall, bytes}], ...}]
        self._digests = {}            # title -> digest of its last picture
        self.left_out, self.left_out_count, self._left_out_seen = [], 0, set()
        self.dirty = True             # something to write
        self.thinned, self.count, self.bytes = 0, 0, 0
        self.notes = []               # the capture's own troubles (composite, errors)
        os.makedirs(directory, exist_ok=True)

    def _window(self, title):
        for window in self.windows:
            if window['title'] == title:
                return window
        return None

    def admits(self, title):
        """May this window be captured? A new title past the windows' limit is
        counted (and named, up to a point), never captured: asked before its
        pixels are read, so a thousand windows cost a thousand titles only."""
        title = clean_title(title)
        if self._window(title) is not None or len(self.windows) < self.max_windows:
            return True
        if title not in self._left_out_seen and len(self._left_out_seen) < MAX_LEFT_OUT_SEEN:
            self._left_out_seen.add(title)
            self.left_out_count += 1
            self.dirty = True
            if len(self.left_out) < LEFT_OUT_NAMED:
                self.left_out.append(title)
        return False

    def wants(self, title, digest):
        """Is a picture of this window, whose pixels' digest is ``digest``, to be
        kept (admitted, and changed since its last one)?"""
        return self.admits(title) and self._digests.get(clean_title(title)) != digest

    def add(self, title, wall, jpeg, digest, size, scaled=False, cut=False):
        """Keep one picture (JPEG bytes) of the window at ``wall``; returns its file."""
        title = clean_title(title)
        window = self._window(title)
        if window is None:
            window = {'title': title, 'pictures': [], 'size': list(size), 'scaled': False,
                      'cut': False}
            self.windows.append(window)
        index = self.windows.index(window)
        self.count += 1
        name = 'w%d_%d.jpg' % (index, self.count)
        with open(os.path.join(self.directory, name), 'wb') as f:
            f.write(jpeg)
        window['pictures'].append({'file': name, 'wall': wall, 'bytes': len(jpeg)})
        window['size'] = list(size)
        window['scaled'] = window['scaled'] or bool(scaled)
        window['cut'] = window['cut'] or bool(cut)
        self._digests[title] = digest
        self.bytes += len(jpeg)
        self.dirty = True
        self._keep_within_limits()
        return name

    def _kept(self):
        return sum(len(w['pictures']) for w in self.windows)

    def _keep_within_limits(self):
        while self._kept() > self.max_pictures or self.bytes > self.max_bytes:
            removed = 0
            for window in self.windows:
                pictures = window['pictures']
                # every second one, counted from the newest (which stays: it is on screen)
                keep = set(range(len(pictures) - 1, -1, -2))
                for i, picture in enumerate(pictures):
                    if i not in keep:
                        self._remove(picture)
                        removed += 1
                window['pictures'] = [p for i, p in enumerate(pictures) if i in keep]
            self.thinned += 1
            self.period *= 2
            if not removed:
                break

    def _remove(self, picture):
        self.bytes -= picture['bytes']
        try:
            os.remove(os.path.join(self.directory, picture['file']))
        except OSError:
            pass

    def as_dict(self):
        return {'period': self.period, 'thinned': self.thinned, 'windows': self.windows,
                'left_out': self.left_out, 'left_out_count': self.left_out_count,
                'notes': self.notes,
                'limits': {'windows': self.max_windows, 'pictures': self.max_pictures,
                           'bytes': self.max_bytes, 'side': MAX_SIDE, 'read': MAX_READ}}

    def write(self):
        """windows.json, replaced whole (a reader never sees half of it)."""
        path = os.path.join(self.directory, INDEX)
        with open(path + '.new', 'w') as f:
            json.dump(self.as_dict(), f)
        os.replace(path + '.new', path)
        self.dirty = False


def read_windows(directory):
    """windows.json of a run's ``display/`` directory, only what it may hold:
    titles as text, pictures that are this module's file names and exist there;
    None when there is none."""
    try:
        with open(os.path.join(directory, INDEX)) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict):
        return None
    windows = []
    for window in data.get('windows') or []:
        if not isinstance(window, dict):
            continue
        pictures = []
        for p in window.get('pictures') or []:
            if isinstance(p, dict) and isinstance(p.get('file'), str) and \
                    PICTURE.match(p['file']) and isinstance(p.get('wall'), (int, float)) and \
                    os.path.isfile(os.path.join(directory, p['file'])):
                pictures.append({'path': os.path.join(directory, p['file']),
                                 'wall': float(p['wall'])})
        size = window.get('size')
        windows.append({'title': clean_title(window.get('title')), 'pictures': pictures,
                        'size': size if isinstance(size, list) else None,
                        'scaled': bool(window.get('scaled')), 'cut': bool(window.get('cut'))})
    return {'windows': windows, 'period': _number(data.get('period')),
            'thinned': _number(data.get('thinned')),
            'left_out': [clean_title(t) for t in (data.get('left_out') or [])
                         if isinstance(t, str)][:LEFT_OUT_NAMED],
            'left_out_count': int(_number(data.get('left_out_count'))),
            'notes': [str(n)[:500] for n in (data.get('notes') or [])][:10],
            'limits': data.get('limits') if isinstance(data.get('limits'), dict) else {}}


def _number(value):
    return float(value) if isinstance(value, (int, float)) else 0.0


def read_clock(record_dir):
    """[(wall s, simulated s)] the truth server heard, in wall order."""
    pairs = []
    try:
        with open(os.path.join(record_dir, 'clock.jsonl')) as f:
            for line in f:
                try:
                    sim, wall = json.loads(line)
                    pairs.append((float(wall), float(sim)))
                except (ValueError, TypeError):
                    continue
    except OSError:
        pass
    return sorted(pairs)


def sim_time(clock, wall):
    """The simulated time at ``wall`` (linear between the pairs around it,
    the first or last one's outside them); None without a clock."""
    if not clock:
        return None
    if wall <= clock[0][0]:
        return clock[0][1]
    if wall >= clock[-1][0]:
        return clock[-1][1]
    lo, hi = 0, len(clock) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if clock[mid][0] <= wall:
            lo = mid
        else:
            hi = mid
    (w0, s0), (w1, s1) = clock[lo], clock[hi]
    return s0 if w1 == w0 else s0 + (s1 - s0) * (wall - w0) / (w1 - w0)


def pace(clock):
    """Simulated s per wall s over the clock (1.0 without one)."""
    if len(clock) < 2 or clock[-1][0] <= clock[0][0] or clock[-1][1] <= clock[0][1]:
        return 1.0
    return (clock[-1][1] - clock[0][1]) / (clock[-1][0] - clock[0][0])


def shown_at(windows, clock, moments, period=1.0):
    """[(window, {moment: picture path or None}, {moment: simulated s})]: at
    each moment (simulated s), the picture of each window taken last before
    it, or within one capture ``period`` (wall s, in simulated s at the run's
    pace) after it: a picture is taken once a period, so that one is the first
    that could show the moment. A picture is kept only when it changed, so
    the last one before is what the window showed. A moment that came before
    the window opened (a node opens its window with its first image, and Qt
    takes a moment) takes the window's first picture, and the third mapping
    says when that was. A moment of None (a run without a clock) takes the
    last picture."""
    slack = period * pace(clock)
    out = []
    for window in windows:
        timed = [(sim_time(clock, p['wall']), p['path']) for p in window['pictures']]
        timed = [(t, path) for t, path in timed if t is not None]
        chosen, opened = {}, {}
        for moment, t in moments.items():
            if t is None:
                chosen[moment] = window['pictures'][-1]['path'] if window['pictures'] else None
                continue
            before = [path for s, path in timed if s <= t + slack]
            chosen[moment] = before[-1] if before else None
            if not before and timed:
                chosen[moment], opened[moment] = timed[0][1], timed[0][0]
        out.append((window, chosen, opened))
    return out


def limit_notes(windows):
    """What the limits cost, for the page, in a teacher's words."""
    notes, limits = [], windows.get('limits') or {}
    notes.append('a picture of each window every %g wall s while it changes; each moment '
                 'shows the last one taken up to one of those after it' % (windows['period'] or 1))
    if windows['left_out_count']:
        notes.append('%d more windows opened and were not captured (at most %d a run): %s' % (
            windows['left_out_count'], limits.get('windows', MAX_WINDOWS),
            ', '.join(windows['left_out'])))
    if windows['thinned']:
        notes.append('pictures thinned to one every %g wall s per window, to stay within %d '
                     'pictures and %d MB a run' % (
                         windows['period'], limits.get('pictures', MAX_PICTURES),
                         limits.get('bytes', MAX_BYTES) // 2 ** 20))
    for window in windows['windows']:
        size = 'x'.join(str(n) for n in window['size'] or [])
        if window['cut']:
            read, side = limits.get('read', MAX_READ), limits.get('side', MAX_SIDE)
            notes.append('"%s" (%s px): only its top-left %d x %d px part was read%s' % (
                window['title'], size, read, read,
                ', scaled down to %d px' % side if window['scaled'] else ''))
        elif window['scaled']:
            notes.append('"%s" (%s px): shown scaled down to %d px' % (
                window['title'], size, limits.get('side', MAX_SIDE)))
    return notes + windows['notes']
