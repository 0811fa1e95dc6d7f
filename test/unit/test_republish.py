"""image_transport's republish stand-in (src/exp_assignment2/original_env/stand_in_packages): its
command line, and the camera's JPEG stream as raw images and back, run as a
launch file runs it."""
import os
import subprocess

import pytest

from exp_assignment2.launch_surface.republish import parse
from original_env_helpers import PYTHON, REPO, run

REPUBLISH = os.path.join(REPO, 'src', 'exp_assignment2', 'original_env', 'stand_in_packages',
                         'image_transport',
                         'scripts', 'republish')


def test_the_transports_as_image_transport_takes_them():
    assert parse(['compressed', 'raw']) == ('compressed', ['raw'])
    assert parse(['raw']) == ('raw', ['compressed', 'raw'])      # no output transport: every one
    for bad in ([], ['theora'], ['raw', 'compressed', 'raw']):
        with pytest.raises(ValueError, match='republish IN_TRANSPORT in:='):
            parse(bad)


# A 64x48 frame (a green square on grey) as the camera's JPEG on /cam/compressed;
# what comes out raw on /raw and, republished again, as JPEG on /jpeg/compressed.
LISTENER = r'''
import threading
import cv2, numpy as np, rospy
from sensor_msgs.msg import CompressedImage, Image
rospy.init_node('listener', disable_signals=True)
frame = np.full((48, 64, 3), 128, np.uint8)
frame[10:30, 20:40] = (0, 200, 0)
jpeg = cv2.imencode('.jpg', frame)[1].tobytes()
got = {}
done = threading.Event()
def keep(name):
    def cb(msg):
        got.setdefault(name, msg)
        if len(got) == 2:
            done.set()
    return cb
rospy.Subscriber('/raw', Image, keep('raw'))
rospy.Subscriber('/jpeg/compressed', CompressedImage, keep('jpeg'))
pub = rospy.Publisher('/cam/compressed', CompressedImage, queue_size=1)
while not done.wait(0.1):
    pub.publish(CompressedImage(format='rgb8; jpeg compressed bgr8', data=jpeg))
raw, back = got['raw'], got['jpeg']
image = np.frombuffer(raw.data, np.uint8).reshape(raw.height, raw.width, 3)
again = cv2.imdecode(np.frombuffer(back.data, np.uint8), cv2.IMREAD_COLOR)
print(raw.encoding, raw.width, raw.height, tuple(int(v) for v in image[20, 30]),
      back.format, again.shape, tuple(int(v) for v in again[20, 30]))
'''


def test_a_jpeg_stream_goes_raw_and_back(ros_master):
    env = dict(ros_master, EXP2_LIBRARY=os.path.join(REPO, 'src'))
    nodes = [subprocess.Popen([PYTHON, REPUBLISH, 'compressed', 'in:=/cam', 'raw', 'out:=/raw',
                               '__name:=decompress'], env=env),
             subprocess.Popen([PYTHON, REPUBLISH, 'raw', 'in:=/raw', 'compressed',
                               'out:=/jpeg', '__name:=compress'], env=env)]
    try:
        proc = run(LISTENER, env, timeout=60)
    finally:
        for node in nodes:
            node.terminate()
            node.wait(10)
    assert proc.returncode == 0, proc.stderr
    words = proc.stdout.split()
    assert words[:3] == ['bgr8', '64', '48']
    green = [int(v.strip('(),')) for v in words[3:6]]
    assert green[0] < 30 and green[1] > 170 and green[2] < 30, words
    assert ' '.join(words[6:10]) == 'bgr8; jpeg compressed bgr8'
    assert words[10:13] == ['(48,', '64,', '3)'], words
