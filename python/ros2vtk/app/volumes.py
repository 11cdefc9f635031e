"""Volumes (CT, MRI) read from files into the scene, for the app's slice panes and 3D view.

    image, file_to_world = read_volume('ct.nrrd')      # ValueError with a reason on a bad file
    node = add_volume_node(scene, image, file_to_world, 'ct')

VTK 9.1's own readers: NRRD (.nrrd, .nhdr: vtkNrrdReader), MetaImage (.mha, .mhd:
vtkMetaImageReader), NIfTI (.nii, .nii.gz: vtkNIFTIImageReader). The image keeps its file's origin
and spacing (mm); a NIfTI file's sform (else qform) matrix, which maps its voxels to RAS mm,
becomes a transform node above the volume node. VTK 9.1's NRRD and MetaImage readers ignore the
file's direction, so it is read from the header here (NRRD `space directions`, MetaImage
`TransformMatrix`): when the axes are rotated, or the file's coordinates are left-posterior-
superior (a NRRD whose `space` says so; every MetaImage, as ITK and Slicer read them), turned into
RAS as Slicer does (x and y negated), the image is read with origin 0 and the file's
voxel-to-world matrix (direction x spacing, origin) becomes that transform node.
"""
from __future__ import annotations

import math
import os

import vtk

# Window/level presets of Slicer's Volumes module (window, level), as Slicer lists them:
# Slicer/Slicer Modules/Loadable/Volumes/Resources/VolumeDisplayPresets.json. (Its PET and DTI
# presets also switch to a rainbow colour table, which the grey slice panes do not have; Slicer
# has no MR preset: an MRI is shown with its automatic window, 'auto' here.)
WINDOW_LEVEL_PRESETS = {'CT-Bone': (1000.0, 400.0), 'CT-Air': (1000.0, -426.0), 'CT-Brain': (100.0, 50.0),
                        'CT-Abdomen': (350.0, 40.0), 'CT-Lung': (1400.0, -500.0)}

READERS = {'.nrrd': 'vtkNrrdReader', '.nhdr': 'vtkNrrdReader', '.mha': 'vtkMetaImageReader',
           '.mhd': 'vtkMetaImageReader', '.nii': 'vtkNIFTIImageReader', '.nii.gz': 'vtkNIFTIImageReader'}
FORMATS = {'vtkNrrdReader': 'NRRD', 'vtkMetaImageReader': 'MetaImage', 'vtkNIFTIImageReader': 'NIfTI'}


def _suffix(path: str) -> str:
    lower = path.lower()
    return '.nii.gz' if lower.endswith('.nii.gz') else os.path.splitext(lower)[1]


def volume_name(path: str) -> str:
    """The file's name without its volume suffix ('ct' for /data/ct.nii.gz)."""
    base = os.path.basename(path)
    suffix = _suffix(base)
    return base[:-len(suffix)] if suffix and base.lower().endswith(suffix) else base


def read_volume(path: str) -> tuple[vtk.vtkImageData, vtk.vtkMatrix4x4 | None]:
    """The 3D image of a volume file, and the matrix from its voxel frame to world mm when the
    file has one (NIfTI), else None. ValueError with a reason for a missing, unknown, unreadable
    or not 3D file."""
    path = os.path.expanduser((path or '').strip())
    if not path:
        raise ValueError('a volume file is required (.nrrd, .nhdr, .mha, .mhd, .nii, .nii.gz)')
    reader_class = READERS.get(_suffix(path))
    if reader_class is None:
        raise ValueError(f'{path}: not a volume file this app reads (.nrrd, .nhdr, .mha, .mhd, .nii, .nii.gz)')
    if not os.path.isfile(path):
        raise ValueError(f'no such file: {path}')
    kind = FORMATS[reader_class]
    if reader_class == 'vtkNrrdReader':
        # Debian's VTK overrides vtkNrrdReader with vtkPNrrdReader (MPI), which refuses every file
        # without an MPI controller ("No MPI Controller available"): the serial reader is used.
        vtk.vtkObjectFactory.SetAllEnableFlags(False, 'vtkNrrdReader')
    reader = getattr(vtk, reader_class)()
    errors: list[str] = []

    @vtk.calldata_type(vtk.VTK_STRING)
    def collect(_caller, _event, text):
        # 'ERROR: In file, line N\nvtkClass (0x...): reason' -> 'reason'
        errors.append(' '.join(str(text).split('): ', 1)[-1].split()))
    # An observed ErrorEvent is not printed: the reason goes into the ValueError instead.
    reader.AddObserver('ErrorEvent', collect)
    reader.GetExecutive().AddObserver('ErrorEvent', collect)
    if not reader.CanReadFile(path):
        raise ValueError(f'{path}: not a readable {kind} file')
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if errors or image is None or image.GetNumberOfPoints() == 0 or image.GetPointData().GetScalars() is None:
        detail = errors[0] if errors else 'no voxels'
        raise ValueError(f'{path}: cannot read this {kind} file ({detail})')
    dims = image.GetDimensions()
    if min(dims) < 2:
        raise ValueError(f'{path}: not a 3D volume ({dims[0]} x {dims[1]} x {dims[2]} voxels)')
    volume = vtk.vtkImageData()
    volume.ShallowCopy(image)  # free of the reader
    matrix = None
    placement = _header_placement(path, reader_class, volume.GetSpacing())
    if placement is not None:
        spacing, matrix = placement
        volume.SetSpacing(*spacing)
        volume.SetOrigin(0.0, 0.0, 0.0)  # the matrix places the voxels
    if reader_class == 'vtkNIFTIImageReader':
        form = reader.GetSFormMatrix() or reader.GetQFormMatrix()
        if form is not None and not _is_identity(form):
            matrix = vtk.vtkMatrix4x4()
            matrix.DeepCopy(form)
    return volume, matrix


def _header_fields(path: str, separator: str) -> dict[str, str]:
    """The `key<separator>value` lines of a text header (NRRD: up to its first blank line;
    MetaImage: up to ElementDataFile), keys lower case."""
    fields = {}
    with open(path, 'rb') as stream:
        for raw in stream:
            line = raw.decode('latin-1').strip()
            if not line:
                break
            key, found, value = line.partition(separator)
            if found and not line.startswith('#'):
                fields[key.strip().lower()] = value.strip()
                if key.strip().lower() == 'elementdatafile':
                    break
    return fields


def _numbers(text: str) -> list[float]:
    return [float(v) for v in text.replace('(', ' ').replace(')', ' ').replace(',', ' ').split()]


NRRD_LPS = ('left-posterior-superior', 'lps')


def _header_placement(path: str, reader_class: str, spacing):
    """The spacing and the matrix from (index x spacing) to world mm that a NRRD or MetaImage
    header gives (columns: each axis's unit direction; last column: the origin; a NRRD in LPS
    space, and every MetaImage, turned into RAS as Slicer does), or None when its axes are the
    world's (the image's origin and spacing then say it all). ValueError for a direction that is
    no 3 x 3 matrix."""
    if reader_class == 'vtkNrrdReader':
        fields = _header_fields(path, ':')
        if 'space directions' not in fields:
            return None
        axes = [a for a in fields['space directions'].replace(')', ')|').split('|') if a.strip()]
        columns = [_numbers(a) for a in axes if a.strip() != 'none']  # direction x spacing
        origin = _numbers(fields.get('space origin', '(0,0,0)'))
        flip = fields.get('space', '').lower() in NRRD_LPS
    elif reader_class == 'vtkMetaImageReader':
        fields = _header_fields(path, '=')
        text = fields.get('transformmatrix') or fields.get('rotation') or fields.get('orientation')
        values = _numbers(text) if text is not None else [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
        # MetaIO lists each axis's direction in turn (ITK's MetaImageIO: axis i = values[3i:3i+3]).
        columns = [[v * spacing[i] for v in values[3 * i:3 * i + 3]] for i in range(len(values) // 3)]
        origin = _numbers(fields.get('offset') or fields.get('position') or fields.get('origin') or '0 0 0')
        # ITK, and so Slicer, takes every MetaImage's coordinates as LPS, whatever its
        # AnatomicalOrientation says (ITK ignores that field: InsightSoftwareConsortium/ITK#1017).
        flip = True
    else:
        return None
    if len(columns) != 3 or any(len(c) != 3 for c in columns) or len(origin) != 3 or \
            any(math.hypot(*c) == 0 for c in columns):
        raise ValueError(f'{path}: its direction is not a 3 x 3 matrix with a 3D origin')
    lengths = [math.hypot(*c) for c in columns]
    unit = [[v / length for v in c] for c, length in zip(columns, lengths)]
    if not flip and all(abs(unit[c][r] - (1.0 if r == c else 0.0)) < 1e-9 for r in range(3) for c in range(3)):
        return None
    sign = (-1.0, -1.0, 1.0) if flip else (1.0, 1.0, 1.0)
    matrix = vtk.vtkMatrix4x4()
    for row in range(3):
        for column in range(3):
            matrix.SetElement(row, column, sign[row] * unit[column][row])
        matrix.SetElement(row, 3, sign[row] * origin[row])
    return lengths, matrix


def _is_identity(matrix: vtk.vtkMatrix4x4) -> bool:
    return all(matrix.GetElement(i, j) == (1.0 if i == j else 0.0) for i in range(4) for j in range(4))


def add_volume_node(scene, image: vtk.vtkImageData, file_to_world: vtk.vtkMatrix4x4 | None, name: str):
    """A vtkROS2VolumeNode holding `image` (window/level: its scalar range), under a transform node
    holding `file_to_world` when given; returns the volume node."""
    import ros2vtk
    node = ros2vtk.vtkROS2VolumeNode()
    node.SetName(name)
    node.SetImageData(image)
    scene.AddNode(node)
    if file_to_world is not None:
        transform = ros2vtk.vtkROS2TransformNode()
        transform.SetName(f'{name}: file to world')
        transform.SetMatrixTransformToParent(file_to_world)
        scene.AddNode(transform)
        node.SetParentTransformNodeID(transform.GetID())
    return node


def remove_volume_node(scene, node) -> None:
    """Removes a volume node and the file-to-world transform node add_volume_node made for it."""
    parent = node.GetParentTransformNode() if hasattr(node, 'GetParentTransformNode') else None
    scene.RemoveNode(node)
    if parent is not None and (parent.GetName() or '').endswith(': file to world'):
        scene.RemoveNode(parent)


def image_of(node) -> vtk.vtkImageData | None:
    """The image a slice source (a volume node) shows."""
    if node is None or not node.IsA('vtkROS2VolumeNode'):
        return None
    return node.GetImageData()


def slice_sources(scene) -> list[dict]:
    """What the slice panes can show: every volume node, as {'value': node ID, 'title': label}
    rows. (No image subscriber: no mapped ROS type gives a 3D image, so none is offered.)"""
    from .scene_state import nodes_of_class
    rows = []
    for node in nodes_of_class(scene, 'vtkROS2VolumeNode'):
        image = node.GetImageData()
        dims = image.GetDimensions() if image is not None else (0, 0, 0)
        rows.append({'value': node.GetID(), 'title': f'{node.GetName()} (volume, {dims[0]}x{dims[1]}x{dims[2]})'})
    return rows
