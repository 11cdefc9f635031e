"""Volume files' directions (python/ros2vtk/app/volumes.py): VTK 9.1's NRRD and MetaImage readers
ignore a file's direction, the app applies it. Each file here is written as header text by hand
(and numpy bytes for the voxels), never by a writer of ours: one bright voxel at a known index,
whose world position is computed here from the header's numbers (origin + direction x spacing x
index; a NRRD in LPS space, and every MetaImage, turned into RAS as Slicer does) and compared with where the scene puts
it (the volume node's image and its file-to-world transform node). A 2D slice view through that
point shows the voxel at the pane's centre."""
from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy
import pytest

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
sys.path.insert(0, str(BUILD / 'python'))

import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

import ros2vtk  # noqa: E402
from ros2vtk.app import volumes  # noqa: E402

DIMS = (12, 5, 4)  # i, j, k (VTK's NRRD reader takes a first axis of 9 or fewer as components)
BRIGHT = (10, 1, 2)  # the bright voxel's index


def voxels() -> bytes:
    data = numpy.zeros(DIMS[::-1], dtype=numpy.uint8)  # k, j, i: the file's order (i fastest)
    data[BRIGHT[2], BRIGHT[1], BRIGHT[0]] = 255
    return data.tobytes()


def where_the_scene_puts_the_bright_voxel(path: Path):
    """World mm of the brightest voxel, as the app places it: the image's own origin and spacing,
    then the volume node's parent transform (file to world) when there is one."""
    image, file_to_world = volumes.read_volume(str(path))
    scene = ros2vtk.vtkROS2Scene()
    node = volumes.add_volume_node(scene, image, file_to_world, path.stem)
    values = vtk_to_numpy(node.GetImageData().GetPointData().GetScalars())
    index = numpy.unravel_index(int(values.argmax()), DIMS[::-1])[::-1]
    assert tuple(int(i) for i in index) == BRIGHT, index
    point = [o + s * i for o, s, i in zip(image.GetOrigin(), image.GetSpacing(), index)] + [1.0]
    to_world = vtk.vtkMatrix4x4()
    parent = node.GetParentTransformNode()
    if parent is not None:
        parent.GetMatrixTransformToWorld(to_world)
    return to_world.MultiplyPoint(point)[:3], node, scene


def write_nrrd(path: Path, space: str, directions: str) -> None:
    """A NRRD file: header text by hand (origin (10, 20, 30)), then the voxels, raw."""
    header = (f'NRRD0004\ntype: uint8\ndimension: 3\nspace: {space}\nsizes: {DIMS[0]} {DIMS[1]} {DIMS[2]}\n'
              f'space directions: {directions}\nkinds: domain domain domain\n'
              'encoding: raw\nspace origin: (10,20,30)\n\n')
    path.write_bytes(header.encode() + voxels())


def write_lps_nrrd(path: Path) -> None:
    # Axis i along +y (2 mm), axis j along -x (3 mm), axis k along +z (4 mm), in LPS.
    write_nrrd(path, 'left-posterior-superior', '(0,2,0) (-3,0,0) (0,0,4)')


def test_nrrd_space_directions_rotated_in_lps_space(tmp_path):
    path = tmp_path / 'rotated.nrrd'
    write_lps_nrrd(path)
    world, *_ = where_the_scene_puts_the_bright_voxel(path)
    i, j, k = BRIGHT
    lps = [10 + j * -3, 20 + i * 2, 30 + k * 4]
    expected = [-lps[0], -lps[1], lps[2]]  # RAS: x and y negated, as Slicer reads LPS files
    assert numpy.allclose(world, expected), (world, expected)


def test_nrrd_in_ras_space_keeps_its_signs(tmp_path):
    path = tmp_path / 'ras.nrrd'
    write_nrrd(path, 'right-anterior-superior', '(0,2,0) (-3,0,0) (0,0,4)')
    world, *_ = where_the_scene_puts_the_bright_voxel(path)
    i, j, k = BRIGHT
    assert numpy.allclose(world, (10 + j * -3, 20 + i * 2, 30 + k * 4)), world


def test_metaimage_transform_matrix(tmp_path):
    (tmp_path / 'rotated.raw').write_bytes(voxels())
    path = tmp_path / 'rotated.mhd'
    # MetaIO lists each axis's direction in turn: i along +y, j along -x, k along +z.
    path.write_text('ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n'
                    'TransformMatrix = 0 1 0 -1 0 0 0 0 1\nOffset = 5 6 7\nElementSpacing = 2 3 4\n'
                    f'DimSize = {DIMS[0]} {DIMS[1]} {DIMS[2]}\nElementType = MET_UCHAR\n'
                    'ElementDataFile = rotated.raw\n')
    world, *_ = where_the_scene_puts_the_bright_voxel(path)
    i, j, k = BRIGHT
    lps = (5 + j * 3 * -1, 6 + i * 2, 7 + k * 4)
    expected = (-lps[0], -lps[1], lps[2])  # RAS: a MetaImage's coordinates are LPS (ITK, Slicer)
    assert numpy.allclose(world, expected), world


def write_plain_metaimage(path: Path, extra: str = '') -> None:
    """An axis-aligned MetaImage (no TransformMatrix), Offset (5, 6, 7), spacing (2, 3, 4)."""
    (path.parent / 'plain.raw').write_bytes(voxels())
    path.write_text('ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n'
                    f'{extra}Offset = 5 6 7\nElementSpacing = 2 3 4\n'
                    f'DimSize = {DIMS[0]} {DIMS[1]} {DIMS[2]}\nElementType = MET_UCHAR\n'
                    'ElementDataFile = plain.raw\n')


def test_an_axis_aligned_metaimage_is_lps_too(tmp_path):
    """No TransformMatrix: the axes are LPS's, so the voxel lands at x and y negated (RAS), as
    Slicer places the same file."""
    path = tmp_path / 'plain.mhd'
    write_plain_metaimage(path)
    world, node, _ = where_the_scene_puts_the_bright_voxel(path)
    i, j, k = BRIGHT
    assert numpy.allclose(world, (-(5 + i * 2), -(6 + j * 3), 7 + k * 4)), world
    assert node.GetParentTransformNode() is not None


def test_a_metaimages_anatomical_orientation_is_ignored_as_itk_does(tmp_path):
    """ITK (so Slicer) reads a MetaImage as LPS whatever its AnatomicalOrientation field says
    (InsightSoftwareConsortium/ITK#1017): a file saying RAS lands where the plain one does."""
    path = tmp_path / 'says_ras.mhd'
    write_plain_metaimage(path, 'AnatomicalOrientation = RAS\n')
    world, *_ = where_the_scene_puts_the_bright_voxel(path)
    i, j, k = BRIGHT
    assert numpy.allclose(world, (-(5 + i * 2), -(6 + j * 3), 7 + k * 4)), world


def test_axis_aligned_files_keep_their_origin_and_no_transform(tmp_path):
    path = tmp_path / 'plain.nrrd'
    write_nrrd(path, 'right-anterior-superior', '(2,0,0) (0,3,0) (0,0,4)')
    world, node, _ = where_the_scene_puts_the_bright_voxel(path)
    assert node.GetParentTransformNode() is None
    i, j, k = BRIGHT
    assert numpy.allclose(world, (10 + i * 2, 20 + j * 3, 30 + k * 4)), world


def test_a_direction_that_is_no_matrix_is_refused(tmp_path):
    path = tmp_path / 'broken.nrrd'
    write_nrrd(path, 'right-anterior-superior', '(0,2,0) (-3,0) (0,0,4)')
    with pytest.raises(ValueError, match='not a 3 x 3 matrix'):
        volumes.read_volume(str(path))


def bright_pixel_in_each_pane(node, scene, world) -> dict:
    """For each orientation: the brightest pixel (x, y, value) of a 200 x 200 slice pane of the
    volume node centred on `world`, 20 mm half height."""
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(200, 200)
    renderer = vtk.vtkRenderer()
    window.AddRenderer(renderer)
    found = {}
    for orientation in ('axial', 'sagittal', 'coronal'):
        view = ros2vtk.vtkROS2SliceView()
        view.SetRenderer(renderer)
        view.SetScene(scene)
        view.SetVolumeNode(node)
        assert view.SetOrientation(orientation)
        view.SetSliceCenter(*world)
        view.SetFieldOfView(20.0)  # half height, mm: a voxel is several pixels
        view.SetWindowLevel(255.0, 127.5)
        view.Update()
        window.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(200, 200, -1)[:, :, 0]
        y, x = numpy.unravel_index(int(pixels.argmax()), pixels.shape)
        found[orientation] = (int(x), int(y), int(pixels[y, x]))
        view.SetRenderer(None)
        renderer.RemoveAllViewProps()
    window.Finalize()  # before the X server ends
    return found


def test_a_slice_view_shows_the_rotated_voxel_at_its_world_point(tmp_path):
    """The app's slice pane (vtkROS2SliceView of the volume node, under its file-to-world
    transform) centred on the bright voxel's world point, computed here from the header, draws
    the voxel at the pane's centre in each orientation."""
    from ros2vtk.app.view import ensure_x_display
    xvfb = ensure_x_display()
    try:
        path = tmp_path / 'rotated.nrrd'
        write_lps_nrrd(path)
        _, node, scene = where_the_scene_puts_the_bright_voxel(path)
        i, j, k = BRIGHT
        ras = (-(10 + j * -3), -(20 + i * 2), 30 + k * 4)  # as in the LPS test above
        found = bright_pixel_in_each_pane(node, scene, ras)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
            os.environ.pop('DISPLAY', None)  # it pointed at that server
    print(f'brightest pixel (x, y, value) per pane: {found}')
    for orientation, (x, y, value) in found.items():
        assert value > 200, f'{orientation}: no bright voxel in the pane ({found})'
        assert abs(x - 100) <= 12 and abs(y - 100) <= 12, f'{orientation}: bright voxel off centre ({found})'
