"""Gazebo's named materials as one colour each (no ROS): the one home of the
colours a URDF's ``<material>Gazebo/NAME</material>`` and an SDF world's
``<script><name>Gazebo/NAME</name></script>`` are drawn in.

Values are Gazebo's own (media/materials/scripts/gazebo.material): each
material's ``diffuse`` colour, the one lighting shades. A textured material
(Wood, WoodFloor, Bricks, Road, Residential) has a white or grey diffuse that
multiplies its picture, which is not drawn here: its colour is the picture's
overall look, said as such. *Transparent ones are half transparent, as their
alpha_op says. Names gazebo.material lacks in later Gazebos (Gray, LightGrey,
DarkYellow, Indigo) keep the colour the name says.
"""

GAZEBO_MATERIALS = {
    # untextured: gazebo.material's diffuse
    'Gazebo/Grey': (0.7, 0.7, 0.7, 1.0), 'Gazebo/DarkGrey': (0.175, 0.175, 0.175, 1.0),
    'Gazebo/White': (1.0, 1.0, 1.0, 1.0), 'Gazebo/FlatBlack': (0.1, 0.1, 0.1, 1.0),
    'Gazebo/Black': (0.0, 0.0, 0.0, 1.0), 'Gazebo/Red': (1.0, 0.0, 0.0, 1.0),
    'Gazebo/RedBright': (0.87, 0.26, 0.07, 1.0), 'Gazebo/Green': (0.0, 1.0, 0.0, 1.0),
    'Gazebo/Blue': (0.0, 0.0, 1.0, 1.0), 'Gazebo/SkyBlue': (0.0, 0.0, 1.0, 1.0),
    'Gazebo/Yellow': (1.0, 1.0, 0.0, 1.0), 'Gazebo/ZincYellow': (0.9725, 0.9529, 0.2078, 1.0),
    'Gazebo/Purple': (1.0, 0.0, 1.0, 1.0), 'Gazebo/Turquoise': (0.0, 1.0, 1.0, 1.0),
    'Gazebo/Orange': (1.0, 0.5088, 0.0468, 1.0), 'Gazebo/Gold': (0.8, 0.64869, 0.120759, 1.0),
    'Gazebo/Pioneer2Body': (0.681193, 0.000923, 0.000923, 1.0),
    'Gazebo/RedGlow': (1.0, 0.0, 0.0, 1.0), 'Gazebo/GreenGlow': (0.0, 1.0, 0.0, 1.0),
    'Gazebo/BlueGlow': (0.0, 0.0, 1.0, 1.0), 'Gazebo/YellowGlow': (1.0, 1.0, 0.0, 1.0),
    'Gazebo/PurpleGlow': (1.0, 0.0, 1.0, 1.0), 'Gazebo/TurquoiseGlow': (0.0, 1.0, 1.0, 1.0),
    'Gazebo/WhiteGlow': (1.0, 1.0, 1.0, 1.0),
    'Gazebo/GreyTransparent': (0.5, 0.5, 0.5, 0.5), 'Gazebo/BlueTransparent': (0.0, 0.0, 1.0, 0.5),
    'Gazebo/GreenTransparent': (0.0, 1.0, 0.0, 0.5), 'Gazebo/RedTransparent': (1.0, 0.0, 0.0, 0.5),
    'Gazebo/YellowTransparent': (1.0, 1.0, 0.0, 0.5),
    'Gazebo/OrangeTransparent': (1.0, 0.44, 0.0, 0.6),
    # textured: the picture's overall look (its diffuse only multiplies it)
    'Gazebo/Wood': (0.65, 0.45, 0.25, 1.0), 'Gazebo/WoodFloor': (0.6, 0.45, 0.3, 1.0),
    'Gazebo/WoodPallet': (0.65, 0.5, 0.35, 1.0), 'Gazebo/Bricks': (0.6, 0.3, 0.2, 1.0),
    'Gazebo/Road': (0.3, 0.3, 0.3, 1.0), 'Gazebo/Residential': (0.6, 0.55, 0.5, 1.0),
    # names later gazebo.material files lack: the colour the name says
    'Gazebo/Gray': (0.7, 0.7, 0.7, 1.0), 'Gazebo/LightGrey': (0.8, 0.8, 0.8, 1.0),
    'Gazebo/DarkYellow': (0.7, 0.7, 0.0, 1.0), 'Gazebo/Indigo': (0.33, 0.0, 0.5, 1.0),
}
UNKNOWN = GAZEBO_MATERIALS['Gazebo/Grey']      # a name Gazebo would not know: drawn grey
