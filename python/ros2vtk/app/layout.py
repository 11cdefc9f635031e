"""The app's one layout file (trame + Vuetify 3): a drawer with one collapsible section per task,
as SlicerROS2's module panel (Robots, Topics, tf, Parameters, Scene), each with its list of nodes
on top and the details of the selected one below; the 3D view fills the page; the status line and
the last action's outcome sit in the footer. Element ids are stable: the browser tests use them.
"""
from __future__ import annotations


def build(app, title):
    """Builds the page; each form button sends its fields with the click (the server applies them
    before acting, so a click never races the field's own state update)."""
    from trame.ui.vuetify3 import SinglePageWithDrawerLayout
    from trame.widgets import html, rca
    from trame.widgets import vuetify3 as v3

    ctrl = app.ctrl
    with SinglePageWithDrawerLayout(app.server, full_height=True) as layout:
        layout.title.set_text(title)
        layout.drawer.width = 600
        with layout.toolbar:
            v3.VSpacer()
            v3.VBtn('Reset view', click=ctrl.reset_camera, variant='text', id='reset_view')

        with layout.drawer:
            with v3.VExpansionPanels(v_model=('panels',), multiple=True, variant='accordion'):
                _robots(v3, html, ctrl)
                _topics(v3, html, ctrl)
                _tf(v3, html, ctrl)
                _parameters(v3, html, ctrl)
                if app.slices is not None:
                    _volumes(v3, html, ctrl)
                _scene(v3, html, ctrl)

        slices = {}
        with layout.content:
            with v3.VContainer(fluid=True, classes='pa-0 fill-height'):
                if app.slices is None:
                    view = rca.RemoteControlledArea(name='view', display='image',
                                                    style='width: 100%; height: 100%;', id='view')
                else:  # the 3D view above, the three slice panes in a row below
                    with html.Div(style='display: flex; flex-direction: column; width: 100%; height: 100%;'):
                        view = rca.RemoteControlledArea(name='view', display='image',
                                                        style='width: 100%; flex: 2 1 0; min-height: 0;', id='view')
                        # Mounted while there is a volume ('auto'), or always (slices=True).
                        with html.Div(style='display: flex; flex: 1 1 0; min-height: 0; gap: 2px; '
                                            'background: #000;', v_if='slices_shown', id='slice_panes'):
                            for orientation in app.slices.ORIENTATIONS:
                                with html.Div(style='flex: 1 1 0; position: relative; min-width: 0;'):
                                    slices[orientation] = rca.RemoteControlledArea(
                                        name=f'slice_{orientation}', display='image',
                                        style='width: 100%; height: 100%;', id=f'slice_{orientation}')
                                    # Slicer's view colours, on a dark tab: readable over the image.
                                    html.Span(orientation, classes='text-caption',
                                              style='position: absolute; left: 4px; top: 4px; padding: 0 6px; '
                                                    'line-height: 18px; border-radius: 3px; '
                                                    'background: rgba(0, 0, 0, 0.65); color: '
                                                    + {'axial': '#f44336', 'sagittal': '#ffeb3b',
                                                       'coronal': '#4caf50'}[orientation])

        with layout.footer:
            html.Span('{{ status }}', id='status', classes='text-caption')
            v3.VSpacer()
            html.Span('{{ message }}', id='message', classes='text-caption',
                      style=("{color: message_kind == 'error' ? '#c62828' : '#2e7d32'}",))
    return view, slices


def _table(v3, html, headers, rows, item, cells, selected=None, key='id', row_id=None, table_id=None):
    """A compact table; clicking a row selects it (`selected` state name) when given."""
    with v3.VTable(density='compact', classes='text-caption', **({'id': table_id} if table_id else {})):
        with html.Thead():
            with html.Tr():
                for header in headers:
                    html.Th(header)
        with html.Tbody():
            attributes = {'v_for': f'{item} in {rows}', 'key': f'{item}.{key}'}
            if selected:
                attributes['click'] = f'{selected} = {item}.{key}'
                attributes['style'] = (f"{{cursor: 'pointer', background: {selected} == {item}.{key} ? '#e3f2fd' : ''}}",)
            if row_id:
                attributes['id'] = (row_id,)
            with html.Tr(**attributes):
                for cell in cells:
                    html.Td('{{ %s }}' % cell)


def _robots(v3, html, ctrl):
    with v3.VExpansionPanel(title='Robots'):
        with v3.VExpansionPanelText():
            _table(v3, html, ['name', 'source', 'state', 'links tracked', 'visuals'], 'robots', 'r',
                   ['r.name', 'r.source', 'r.state', 'r.links', 'r.visuals'], selected='robot_selected',
                   key='name', row_id="'robot-' + r.name")
            with html.Div(v_if='robot_selected', classes='mt-2'):
                html.Div('Links of {{ robot_selected }}', classes='text-subtitle-2')
                _table(v3, html, ['link', 'status'], 'robot_links', 'l', ['l.link', 'l.status'], key='link')
                html.Pre('{{ robot_warnings }}', v_if='robot_warnings', id='robot_warnings',
                         style='white-space: pre-wrap; color: #b71c1c; font-size: 11px')
                v3.VBtn('Remove robot', click=ctrl.remove_robot, color='error', size='small', variant='tonal',
                        id='robot_remove')
            v3.VDivider(classes='my-2')
            html.Div('Add a robot', classes='text-subtitle-2')
            v3.VTextField(label='name', v_model=('robot_name',), density='compact', id='robot_name')
            with v3.VBtnToggle(v_model=('robot_source',), mandatory=True, density='compact'):
                v3.VBtn('parameter', value='parameter', id='robot_source_parameter')
                v3.VBtn('topic', value='topic', id='robot_source_topic')
                v3.VBtn('file', value='file', id='robot_source_file')
            with html.Div(v_if="robot_source == 'parameter'", classes='d-flex ga-2 mt-2'):
                v3.VTextField(label='parameter node', v_model=('robot_param_node',), density='compact',
                              id='robot_param_node')
                v3.VTextField(label='parameter name', v_model=('robot_param_name',), density='compact',
                              id='robot_param_name')
            v3.VTextField(label='topic (transient local)', v_model=('robot_topic',), density='compact',
                          v_if="robot_source == 'topic'", id='robot_topic', classes='mt-2')
            v3.VTextField(label='URDF file on the server', v_model=('robot_file',), density='compact',
                          v_if="robot_source == 'file'", id='robot_file', classes='mt-2')
            with html.Div(classes='d-flex ga-2'):
                v3.VTextField(label="fixed frame (empty: the scene's, else the root link)", v_model=('robot_fixed_frame',),
                              density='compact', id='robot_fixed_frame')
                v3.VTextField(label='tf prefix', v_model=('robot_tf_prefix',), density='compact', id='robot_tf_prefix')
            v3.VTextField(label='mesh base folder (for relative mesh paths)', v_model=('robot_mesh_base',),
                          density='compact', id='robot_mesh_base')
            v3.VTextField(label='mesh search folders (package:// roots, colon-separated)',
                          v_model=('robot_mesh_paths',), density='compact', id='robot_mesh_paths')
            v3.VBtn('Add robot', click=(ctrl.add_robot, "[{robot_name: robot_name, robot_source: robot_source, robot_param_node: robot_param_node, robot_param_name: robot_param_name, robot_topic: robot_topic, robot_file: robot_file, robot_fixed_frame: robot_fixed_frame, robot_tf_prefix: robot_tf_prefix, robot_mesh_base: robot_mesh_base, robot_mesh_paths: robot_mesh_paths}]"), color='primary', size='small', id='robot_add')


def _topics(v3, html, ctrl):
    with v3.VExpansionPanel(title='Topics'):
        with v3.VExpansionPanelText():
            _table(v3, html, ['', 'topic', 'type', 'QoS', 'matched', 'count', 'rate/s'], 'topics', 't',
                   ["t.direction == 'publisher' ? 'pub' : 'sub'", 't.topic', 't.type', 't.qos', 't.matched',
                    't.count', 't.rate'], selected='topic_selected', row_id="'topic-' + t.direction + '-' + t.topic")
            with html.Div(v_if='topic_selected', classes='mt-2'):
                html.Div('Last message', classes='text-subtitle-2', v_if='topic_yaml')
                html.Pre('{{ topic_yaml }}', id='topic_yaml', v_if='topic_yaml',
                         style='max-height: 200px; overflow: auto; font-size: 11px; background: #f5f5f5')
                v3.VTextarea(label='message (YAML)', v_model=('publish_yaml',), rows=2, density='compact',
                             id='publish_yaml')
                with html.Div(classes='d-flex ga-2'):
                    v3.VBtn('Publish', click=(ctrl.publish, "[{topic_selected: topic_selected, publish_yaml: publish_yaml}]"), color='primary', size='small', id='publish')
                    v3.VBtn('Remove', click=ctrl.remove_topic, color='error', size='small', variant='tonal',
                            id='topic_remove')
            v3.VDivider(classes='my-2')
            html.Div('Add a publisher or subscriber', classes='text-subtitle-2')
            with v3.VBtnToggle(v_model=('topic_direction',), mandatory=True, density='compact'):
                v3.VBtn('subscriber', value='subscriber', id='topic_direction_subscriber')
                v3.VBtn('publisher', value='publisher', id='topic_direction_publisher')
            with html.Div(classes='d-flex ga-2 mt-2'):
                v3.VCombobox(label='type (short name or pkg/msg/Type)', v_model=('topic_type',), density='compact',
                             items=("topic_direction == 'publisher' ? types_publishers : types_subscribers",),
                             id='topic_type')
                v3.VTextField(label='topic', v_model=('topic_name',), density='compact', id='topic_name')
            v3.VBtn('Add', click=(ctrl.add_topic, "[{topic_direction: topic_direction, topic_type: topic_type, topic_name: topic_name}]"), color='primary', size='small', id='topic_add')
            v3.VDivider(classes='my-2')
            html.Div('ROS graph', classes='text-subtitle-2')
            v3.VTextField(label='filter', v_model=('graph_filter',), density='compact', id='graph_filter')
            html.Div('nodes: {{ graph_nodes.join(", ") }}', classes='text-caption', id='graph_nodes')
            _table(v3, html, ['topic', 'types'], 'graph_topics', 'g', ['g.topic', 'g.types'], key='topic')


def _tf(v3, html, ctrl):
    with v3.VExpansionPanel(title='tf'):
        with v3.VExpansionPanelText():
            html.Div('Frames ({{ tf_frames.length }}): age of the newest transform, the node that sent it',
                     classes='text-subtitle-2')
            html.Div('{{ p.topic }} published by {{ p.nodes }}', v_for='p in tf_publishers', key='p.topic',
                     classes='text-caption', id=("'tf-publishers-' + p.topic.slice(1)",))
            with v3.VTable(density='compact', classes='text-caption', id='tf_frames'):
                with html.Thead():
                    with html.Tr():
                        # Narrow cells: five columns, the publisher in view in the 600 px drawer.
                        for header in ('frame', 'parent', 'age', 'rate/s', 'publisher'):
                            html.Th(header, style='padding: 0 4px')
                with html.Tbody():
                    with html.Tr(v_for='f in tf_frames', key='f.frame', id=("'tf-frame-' + f.frame",)):
                        html.Td('{{ f.depth ? "\u2514 " : "" }}{{ f.frame }}',
                                style=("{paddingLeft: (4 + 12 * f.depth) + 'px', paddingRight: '4px', whiteSpace: 'nowrap'}",))
                        html.Td('{{ f.parent }}', style='padding: 0 4px')
                        html.Td('{{ f.age }}', style='padding: 0 4px; white-space: nowrap')  # "0.008 s" on one line
                        html.Td('{{ f.rate }}', style='padding: 0 4px')
                        html.Td('{{ f.publisher }}', style='padding: 0 4px; white-space: nowrap')
            html.Div('Lookups', classes='text-subtitle-2')
            _table(v3, html, ['parent', 'child', 'status'], 'tf_lookups', 'x', ['x.parent', 'x.child', 'x.status'])
            html.Div('Broadcasters', classes='text-subtitle-2')
            _table(v3, html, ['parent', 'child', 'static', 'sent'], 'tf_broadcasters', 'x',
                   ['x.parent', 'x.child', 'x.static', 'x.count'])
            with html.Div(classes='d-flex ga-2 mt-2'):
                v3.VTextField(label='parent frame', v_model=('tf_parent',), density='compact', id='tf_parent')
                v3.VTextField(label='child frame', v_model=('tf_child',), density='compact', id='tf_child')
                v3.VCheckbox(label='static', v_model=('tf_static',), density='compact')
            with html.Div(classes='d-flex ga-2'):
                v3.VBtn('Add lookup', click=(ctrl.add_lookup, "[{tf_parent: tf_parent, tf_child: tf_child}]"), size='small', id='tf_add_lookup')
                v3.VBtn('Add broadcaster', click=(ctrl.add_broadcaster, "[{tf_parent: tf_parent, tf_child: tf_child, tf_static: tf_static}]"), size='small', id='tf_add_broadcaster')


def _parameters(v3, html, ctrl):
    with v3.VExpansionPanel(title='Parameters'):
        with v3.VExpansionPanelText():
            _table(v3, html, ['node', 'name', 'type', 'value'], 'parameters', 'p',
                   ['p.node', 'p.name', 'p.type', 'p.value'], key='name', table_id='parameters')
            with html.Div(classes='d-flex ga-2 mt-2'):
                v3.VTextField(label='node', v_model=('param_node',), density='compact', id='param_node')
                v3.VTextField(label='parameter names', v_model=('param_names',), density='compact', id='param_names')
            v3.VBtn('Watch', click=(ctrl.watch_parameters, "[{param_node: param_node, param_names: param_names}]"), size='small', id='param_watch')
            html.Div('Parameters of our node', classes='text-subtitle-2 mt-2')
            with html.Div(classes='d-flex ga-2'):
                v3.VTextField(label='name', v_model=('own_param_name',), density='compact', id='own_param_name')
                v3.VSelect(label='type', v_model=('own_param_type',), items=('parameter_types',), id='own_param_type',
                           density='compact')
                v3.VTextField(label='value (arrays: a list, [1, 2, 3])', v_model=('own_param_value',), density='compact',
                              id='own_param_value')
            v3.VBtn('Set', click=(ctrl.set_own_parameter, "[{own_param_name: own_param_name, own_param_type: own_param_type, own_param_value: own_param_value}]"), size='small', id='own_param_set')
            html.Div("Set a parameter of another node (its set_parameters service)", classes='text-subtitle-2 mt-2')
            with html.Div(classes='d-flex ga-2'):
                v3.VTextField(label='node', v_model=('remote_param_node',), density='compact', id='remote_param_node')
                v3.VTextField(label='name', v_model=('remote_param_name',), density='compact', id='remote_param_name')
            with html.Div(classes='d-flex ga-2'):
                v3.VSelect(label='type', v_model=('remote_param_type',),
                           items=('parameter_types',), density='compact', id='remote_param_type')
                v3.VTextField(label='value (arrays: a list, [1, 2, 3])', v_model=('remote_param_value',),
                              density='compact', id='remote_param_value')
            v3.VBtn('Set on node', click=(ctrl.set_remote_parameter, "[{remote_param_node: remote_param_node, remote_param_name: remote_param_name, remote_param_type: remote_param_type, remote_param_value: remote_param_value}]"), size='small', id='remote_param_set')
            html.Div('{{ remote_param_result }}', classes='text-caption', id='remote_param_result')


def preset_id(name: str) -> str:
    """The element id of a window/level preset's button ('CT-Bone' -> 'volume_preset_ct_bone')."""
    return 'volume_preset_' + name.lower().replace('-', '_')


def _volumes(v3, html, ctrl):
    from .volumes import WINDOW_LEVEL_PRESETS
    with v3.VExpansionPanel(title='Volumes'):
        with v3.VExpansionPanelText():
            v3.VTextField(label='volume file on the server (.nrrd .nhdr .mha .mhd .nii .nii.gz)',
                          v_model=('volume_file',), density='compact', id='volume_file')
            v3.VBtn('Open volume', click=(ctrl.open_volume, "[{volume_file: volume_file}]"), size='small',
                    color='primary', id='volume_open')
            v3.VSelect(label='shown in the slice panes', v_model=('slice_source',), items=('slice_sources',),
                       item_title='title', item_value='value', density='compact', classes='mt-2',
                       no_data_text='no volume yet: open a file', id='slice_source')
            with html.Div(classes='d-flex ga-2 mt-2', v_if='slice_source'):
                v3.VTextField(label='window (empty: scalar range)', v_model=('volume_window',), density='compact',
                              id='volume_window')
                v3.VTextField(label='level', v_model=('volume_level',), density='compact', id='volume_level')
            v3.VBtn('Set window/level', click=(ctrl.set_window_level, "[{slice_source: slice_source, "
                    "volume_window: volume_window, volume_level: volume_level}]"), size='small',
                    v_if='slice_source', id='volume_window_level')
            # Slicer's Volumes module presets, plus 'auto' (the volume's scalar range): one click each.
            with html.Div(classes='d-flex flex-wrap ga-1 mt-1', v_if='slice_source', id='volume_presets'):
                for name in ('auto', *WINDOW_LEVEL_PRESETS):
                    v3.VBtn(name, click=(ctrl.set_window_preset, f"['{name}', {{slice_source: slice_source}}]"),
                            size='x-small', variant='tonal', id=preset_id(name))
            v3.VBtn('Remove volume', click=ctrl.remove_volume, size='small', color='error', variant='tonal',
                    v_if='slice_source', id='volume_remove')


def _scene(v3, html, ctrl):
    with v3.VExpansionPanel(title='Scene'):
        with v3.VExpansionPanelText():
            v3.VTextField(label='scene file (on the server)', v_model=('scene_file',), density='compact', id='scene_file')
            with html.Div(classes='d-flex ga-2'):
                v3.VBtn('Save', click=(ctrl.save_scene, "[{scene_file: scene_file}]"), size='small', id='scene_save')
                v3.VBtn('Load', click=(ctrl.load_scene, "[{scene_file: scene_file}]"), size='small', id='scene_load')
            html.Div('Errors', classes='text-subtitle-2 mt-2', v_if='errors.length')
            html.Pre('{{ errors.join("\\n") }}', v_if='errors.length', id='errors',
                     style='white-space: pre-wrap; color: #b71c1c; font-size: 11px')
