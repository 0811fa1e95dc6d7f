"""The stand-in message packages (tools/stand_ins/) have the real packages'
md5sums, so their clients and servers interoperate with a real Gazebo's and
ros_control's. Needs the catkin workspace (tools/run builds them)."""
import pytest

gazebo_msgs = pytest.importorskip('gazebo_msgs.srv', reason='the workspace is not sourced')
controller_manager_msgs = pytest.importorskip('controller_manager_msgs.srv')
control_msgs = pytest.importorskip('control_msgs.msg')

# md5sums of ROS 1 Noetic's gazebo_msgs, controller_manager_msgs and control_msgs
REAL = {
    'gazebo_msgs/LinkState': '0818ebbf28ce3a08d48ab1eaa7309ebe',
    'gazebo_msgs/LinkStates': '48c080191eb15c41858319b4d8a609c2',
    'gazebo_msgs/ModelState': '9330fd35f2fcd82d457e54bd54e10593',
    'gazebo_msgs/ModelStates': '48c080191eb15c41858319b4d8a609c2',
    'gazebo_msgs/SpawnModel': '9ed9c82c96abe1a00c3e8cdaeee24413',
    'gazebo_msgs/GetModelState': '4c515e936d3319c9610c559c60bfc3d4',
    'gazebo_msgs/GetModelProperties': '5717f7bd34ed990fa80e28b3015027a3',
    'controller_manager_msgs/SwitchController': 'b29a7abc673b2c54c14b54e50f8d06a5',
    'controller_manager_msgs/ListControllers': '1341feb2e63fa791f855565d0da950d8',
    'control_msgs/JointControllerState': '987ad85e4756f3aef7f1e5e7fe0595d1',
    'control_msgs/JointTrajectoryControllerState': '10817c60c2486ef6b33e97dcd87f4474',
    'control_msgs/PidState': 'b138ec00e886c10e73f27e8712252ea6',
    'control_msgs/JointJog': '1685da700c8c2e1254afc92a5fb89c96',
    'control_msgs/PointHeadAction': '7252920f1243de1b741f14f214125371',
    'control_msgs/SingleJointPositionAction': 'c4a786b7d53e5d0983decf967a5a779e',
}


@pytest.mark.parametrize('name', sorted(REAL))
def test_md5sum_is_the_real_packages(name):
    pkg, typ = name.split('/')
    msg, srv = (__import__(pkg + kind, fromlist=['*']) for kind in ('.msg', '.srv'))
    cls = getattr(msg, typ, None) or getattr(srv, typ)
    assert cls._md5sum == REAL[name]


def test_a_state_message_round_trips():
    import io
    from geometry_msgs.msg import Point, Pose
    from gazebo_msgs.msg import LinkState
    buff = io.BytesIO()
    LinkState(link_name='ball::link', pose=Pose(position=Point(1, 2, 3))).serialize(buff)
    back = LinkState().deserialize(buff.getvalue())
    assert (back.link_name, back.pose.position.z) == ('ball::link', 3.0)
