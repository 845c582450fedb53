<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="es" sourcelanguage="en">
<context>
    <name>FocusPick</name>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>Elegir el enfoque funciona a través de una cámara de la escena: seleccione una y mire a través de ella (0) primero.</translation>
    </message>
    <message>
        <source>Pick focus: %1 follows its camera path, whose keys set the focus; edit them in the timeline.</source>
        <translation>Elegir enfoque: %1 sigue su trayectoria, cuyas claves fijan el enfoque; edítelas en la línea de tiempo.</translation>
    </message>
    <message>
        <source>Pick focus: nothing under the cursor, the focus distance is unchanged.</source>
        <translation>Elegir enfoque: nada bajo el cursor, la distancia de enfoque no cambia.</translation>
    </message>
    <message>
        <source>Pick focus: the surface is behind the camera, the focus distance is unchanged.</source>
        <translation>Elegir enfoque: la superficie está detrás de la cámara, la distancia de enfoque no cambia.</translation>
    </message>
    <message>
        <source>Focus distance of %1: %2 m (%3)</source>
        <translation>Distancia de enfoque de %1: %2 m (%3)</translation>
    </message>
</context>
<context>
    <name>OverlayPainter</name>
    <message>
        <source>BVH nodes + primitives</source>
        <translation>Nodos BVH + primitivas</translation>
    </message>
</context>
<context>
    <name>glint::editor</name>
    <message>
        <source>%1 cannot be read as an image: %2</source>
        <translation>%1 no se puede leer como imagen: %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted: %2</source>
        <translation>%1 no se puede convertir: %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted to PNG: %2</source>
        <translation>%1 no se puede convertir a PNG: %2</translation>
    </message>
    <message>
        <source>The material no longer exists.</source>
        <translation>El material ya no existe.</translation>
    </message>
    <message>
        <source>A material needs a name.</source>
        <translation>Un material necesita un nombre.</translation>
    </message>
    <message>
        <source>Delete unused materials</source>
        <translation>Eliminar materiales no usados</translation>
    </message>
    <message>
        <source>Select a shape or a mesh to assign the material to.</source>
        <translation>Seleccione una forma o una malla a la que asignar el material.</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Asignar material</translation>
    </message>
    <message>
        <source>The mesh no longer exists.</source>
        <translation>La malla ya no existe.</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 no existe.</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 no se puede leer: %2</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 está vacío.</translation>
    </message>
    <message>
        <source>Load texture %1</source>
        <translation>Cargar textura %1</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Clave de transformación</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Pegar clave</translation>
    </message>
</context>
<context>
    <name>glint::editor::Autosave</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>No se puede crear la carpeta de guardado automático %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::ColorField</name>
    <message>
        <source>Choose a colour</source>
        <translation>Elegir un color</translation>
    </message>
    <message>
        <source>%1 (sRGB); stored linear: %2, %3, %4</source>
        <translation>%1 (sRGB); guardado en lineal: %2, %3, %4</translation>
    </message>
</context>
<context>
    <name>glint::editor::CommandLabels</name>
    <message>
        <source>Rename</source>
        <translation>Renombrar</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Mover</translation>
    </message>
    <message>
        <source>Show/hide</source>
        <translation>Mostrar/ocultar</translation>
    </message>
    <message>
        <source>Edit component</source>
        <translation>Editar componente</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Cambiar padre</translation>
    </message>
    <message>
        <source>Edit settings</source>
        <translation>Editar ajustes</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <source>Add camera key</source>
        <translation>Añadir clave de cámara</translation>
    </message>
    <message>
        <source>Edit camera key</source>
        <translation>Editar clave de cámara</translation>
    </message>
    <message>
        <source>Move camera key</source>
        <translation>Mover clave de cámara</translation>
    </message>
    <message>
        <source>Remove camera key</source>
        <translation>Quitar clave de cámara</translation>
    </message>
    <message>
        <source>Camera path mode</source>
        <translation>Modo de trayectoria de cámara</translation>
    </message>
    <message>
        <source>mesh</source>
        <translation>malla</translation>
    </message>
    <message>
        <source>material</source>
        <translation>material</translation>
    </message>
    <message>
        <source>texture</source>
        <translation>textura</translation>
    </message>
    <message>
        <source>image</source>
        <translation>imagen</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>muestreador</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Añadir %1</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>Quitar %1</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>Duplicar %1</translation>
    </message>
    <message>
        <source>Edit %1</source>
        <translation>Editar %1</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importar %1</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Rotar</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Escalar</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformación</translation>
    </message>
    <message>
        <source>Change configuration</source>
        <translation>Cambiar configuración</translation>
    </message>
    <message>
        <source>Change image size</source>
        <translation>Cambiar tamaño de imagen</translation>
    </message>
    <message>
        <source>Change samples per pixel</source>
        <translation>Cambiar muestras por píxel</translation>
    </message>
    <message>
        <source>Change bounces</source>
        <translation>Cambiar rebotes</translation>
    </message>
    <message>
        <source>Change seed</source>
        <translation>Cambiar semilla</translation>
    </message>
    <message>
        <source>Change exposure</source>
        <translation>Cambiar exposición</translation>
    </message>
    <message>
        <source>Change tonemapper</source>
        <translation>Cambiar mapeo tonal</translation>
    </message>
    <message>
        <source>Change radiance clamp</source>
        <translation>Cambiar límite de radiancia</translation>
    </message>
    <message>
        <source>Change TAA settings</source>
        <translation>Cambiar ajustes de TAA</translation>
    </message>
    <message>
        <source>Change SVGF settings</source>
        <translation>Cambiar ajustes de SVGF</translation>
    </message>
    <message>
        <source>Change environment image</source>
        <translation>Cambiar imagen de entorno</translation>
    </message>
    <message>
        <source>Change environment colour</source>
        <translation>Cambiar color de entorno</translation>
    </message>
    <message>
        <source>Change environment intensity</source>
        <translation>Cambiar intensidad de entorno</translation>
    </message>
    <message>
        <source>Rotate environment</source>
        <translation>Rotar entorno</translation>
    </message>
    <message>
        <source>Change active camera</source>
        <translation>Cambiar cámara activa</translation>
    </message>
    <message>
        <source>Change timeline range</source>
        <translation>Cambiar rango de la línea de tiempo</translation>
    </message>
    <message>
        <source>Change frame rate</source>
        <translation>Cambiar fotogramas por segundo</translation>
    </message>
    <message>
        <source>Change output</source>
        <translation>Cambiar salida</translation>
    </message>
    <message>
        <source>Change light units</source>
        <translation>Cambiar unidades de luz</translation>
    </message>
    <message>
        <source>Change light type</source>
        <translation>Cambiar tipo de luz</translation>
    </message>
    <message>
        <source>Change light colour</source>
        <translation>Cambiar color de la luz</translation>
    </message>
    <message>
        <source>Change light intensity</source>
        <translation>Cambiar intensidad de la luz</translation>
    </message>
    <message>
        <source>Change light range</source>
        <translation>Cambiar alcance de la luz</translation>
    </message>
    <message>
        <source>Change light radius</source>
        <translation>Cambiar radio de la luz</translation>
    </message>
    <message>
        <source>Change spot cone</source>
        <translation>Cambiar cono del foco</translation>
    </message>
    <message>
        <source>Change sun size</source>
        <translation>Cambiar tamaño del sol</translation>
    </message>
    <message>
        <source>Change projection</source>
        <translation>Cambiar proyección</translation>
    </message>
    <message>
        <source>Change field of view</source>
        <translation>Cambiar campo de visión</translation>
    </message>
    <message>
        <source>Change aperture</source>
        <translation>Cambiar apertura</translation>
    </message>
    <message>
        <source>Change focus distance</source>
        <translation>Cambiar distancia de enfoque</translation>
    </message>
    <message>
        <source>Change clipping</source>
        <translation>Cambiar recorte</translation>
    </message>
    <message>
        <source>Change aspect ratio</source>
        <translation>Cambiar relación de aspecto</translation>
    </message>
    <message>
        <source>Change shape</source>
        <translation>Cambiar forma</translation>
    </message>
    <message>
        <source>Change radius</source>
        <translation>Cambiar radio</translation>
    </message>
    <message>
        <source>Change height</source>
        <translation>Cambiar altura</translation>
    </message>
    <message>
        <source>Change size</source>
        <translation>Cambiar tamaño</translation>
    </message>
    <message>
        <source>Change material</source>
        <translation>Cambiar material</translation>
    </message>
    <message>
        <source>Change base colour</source>
        <translation>Cambiar color base</translation>
    </message>
    <message>
        <source>Change opacity</source>
        <translation>Cambiar opacidad</translation>
    </message>
    <message>
        <source>Change metallic</source>
        <translation>Cambiar metálico</translation>
    </message>
    <message>
        <source>Change roughness</source>
        <translation>Cambiar rugosidad</translation>
    </message>
    <message>
        <source>Change emission</source>
        <translation>Cambiar emisión</translation>
    </message>
    <message>
        <source>Change emission strength</source>
        <translation>Cambiar intensidad de emisión</translation>
    </message>
    <message>
        <source>Change specular</source>
        <translation>Cambiar especular</translation>
    </message>
    <message>
        <source>Change transmission</source>
        <translation>Cambiar transmisión</translation>
    </message>
    <message>
        <source>Change index of refraction</source>
        <translation>Cambiar índice de refracción</translation>
    </message>
    <message>
        <source>Change volume</source>
        <translation>Cambiar volumen</translation>
    </message>
    <message>
        <source>Change alpha mode</source>
        <translation>Cambiar modo alfa</translation>
    </message>
    <message>
        <source>Change double sided</source>
        <translation>Cambiar doble cara</translation>
    </message>
    <message>
        <source>Change texture</source>
        <translation>Cambiar textura</translation>
    </message>
    <message>
        <source>Rename material</source>
        <translation>Renombrar material</translation>
    </message>
    <message>
        <source>Change bloom</source>
        <translation>Cambiar bloom</translation>
    </message>
    <message>
        <source>New material</source>
        <translation>Material nuevo</translation>
    </message>
    <message>
        <source>Duplicate material</source>
        <translation>Duplicar material</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Asignar material</translation>
    </message>
    <message>
        <source>Change motion blur</source>
        <translation>Cambiar desenfoque de movimiento</translation>
    </message>
    <message>
        <source>Change adaptive sampling</source>
        <translation>Cambiar muestreo adaptativo</translation>
    </message>
    <message>
        <source>Change fog</source>
        <translation>Cambiar niebla</translation>
    </message>
    <message>
        <source>Add studio environment</source>
        <translation>Añadir entorno de estudio</translation>
    </message>
    <message>
        <source>Change sample blocks</source>
        <translation>Cambiar bloques de muestras</translation>
    </message>
</context>
<context>
    <name>glint::editor::Configurations</name>
    <message>
        <source>Baseline</source>
        <translation>Baseline</translation>
    </message>
    <message>
        <source>Realistic</source>
        <translation>Realistic</translation>
    </message>
    <message>
        <source>Full</source>
        <translation>Full</translation>
    </message>
    <message>
        <source>Heavy</source>
        <translation>Heavy</translation>
    </message>
    <message>
        <source>Accumulate</source>
        <translation>Accumulate</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Reference</translation>
    </message>
</context>
<context>
    <name>glint::editor::Document</name>
    <message>
        <source>The scene has no file name yet: use Save As.</source>
        <translation>La escena aún no tiene nombre de archivo: use Guardar como.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importar %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
</context>
<context>
    <name>glint::editor::EditOperations</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>No hay nada seleccionado.</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <source>The node no longer exists.</source>
        <translation>El nodo ya no existe.</translation>
    </message>
    <message>
        <source>A node cannot be moved into itself or its own children.</source>
        <translation>Un nodo no puede moverse dentro de sí mismo ni de sus hijos.</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Cambiar padre</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Añadir %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::ExportDialog</name>
    <message>
        <source>Export image</source>
        <translation>Exportar imagen</translation>
    </message>
    <message>
        <source>Export animation</source>
        <translation>Exportar animación</translation>
    </message>
    <message>
        <source>Output file</source>
        <translation>Archivo de salida</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>Images (*.exr *.png *.jpg *.tif)</source>
        <translation>Imágenes (*.exr *.png *.jpg *.tif)</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Salida</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Ancho</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Alto</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Tamaño</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configuración</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Muestras por píxel</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Semilla</translation>
    </message>
    <message>
        <source>EXR layers</source>
        <translation>Capas EXR</translation>
    </message>
    <message>
        <source>all, none, or a list of albedo, normal, depth, id, variance</source>
        <translation>all, none, o una lista de albedo, normal, depth, id, variance</translation>
    </message>
    <message>
        <source>Render passes</source>
        <translation>Pases de render</translation>
    </message>
    <message>
        <source>EXR only, Accumulate and Reference: none, all, light, or a list of DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</source>
        <translation>Solo EXR, Accumulate y Reference: none, all, light o una lista de DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animación</translation>
    </message>
    <message>
        <source>First frame</source>
        <translation>Primer fotograma</translation>
    </message>
    <message>
        <source>Last frame</source>
        <translation>Último fotograma</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Fotogramas</translation>
    </message>
    <message>
        <source>Video file</source>
        <translation>Archivo de vídeo</translation>
    </message>
    <message>
        <source>optional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</source>
        <translation>opcional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Vídeo</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>Rendering...</source>
        <translation>Renderizando...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryModel</name>
    <message>
        <source>&lt;empty&gt;</source>
        <translation>&lt;vacío&gt;</translation>
    </message>
    <message>
        <source> (saved)</source>
        <translation> (guardado)</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryPanel</name>
    <message>
        <source>Undo history</source>
        <translation>Historial de deshacer</translation>
    </message>
</context>
<context>
    <name>glint::editor::KeyedTransform</name>
    <message>
        <source>Transform and key</source>
        <translation>Transformar e insertar clave</translation>
    </message>
</context>
<context>
    <name>glint::editor::LoadProgress</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1, %2 s</source>
        <translation>%1, %2 s</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Stop reading the file; the open scene stays as it is</source>
        <translation>Detiene la lectura del archivo; la escena abierta queda como está</translation>
    </message>
    <message>
        <source>Loading progress</source>
        <translation>Progreso de la carga</translation>
    </message>
</context>
<context>
    <name>glint::editor::LogPanel</name>
    <message>
        <source>Log messages</source>
        <translation>Mensajes del registro</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>Clear the log</source>
        <translation>Borrar el registro</translation>
    </message>
    <message>
        <source>info</source>
        <translation>info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>aviso</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
</context>
<context>
    <name>glint::editor::MainWindow</name>
    <message>
        <source>Glint scene editor</source>
        <translation>Editor de escenas Glint</translation>
    </message>
    <message>
        <source>Scene to open</source>
        <translation>Escena que abrir</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Falló el guardado automático: %1</translation>
    </message>
    <message>
        <source>The viewport is not available in this build.</source>
        <translation>La vista no está disponible en esta compilación.</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Esquema</translation>
    </message>
    <message>
        <source>Undo history</source>
        <translation>Historial de deshacer</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propiedades</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Escena</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <source>Nothing selected</source>
        <translation>Nada seleccionado</translation>
    </message>
    <message>
        <source>Selected: %1</source>
        <translation>Seleccionado: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes selected</source>
        <translation><numerusform>%n nodo seleccionado</numerusform><numerusform>%n nodos seleccionados</numerusform></translation>
    </message>
    <message>
        <source>Selection</source>
        <translation>Selección</translation>
    </message>
    <message>
        <source>Scene statistics</source>
        <translation>Estadísticas de la escena</translation>
    </message>
    <message>
        <source>Render progress</source>
        <translation>Progreso del render</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>"%1" has unsaved changes. Save them first?</source>
        <translation>"%1" tiene cambios sin guardar. ¿Guardarlos primero?</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>No se puede abrir %1: %2</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Abierto %1</translation>
    </message>
    <message>
        <source>Cannot import %1: %2</source>
        <translation>No se puede importar %1: %2</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>Importado %1</translation>
    </message>
    <message>
        <source>Cannot save: %1</source>
        <translation>No se puede guardar: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Guardado %1</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Guardar escena</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb)</source>
        <translation>Escenas glTF (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>No se puede guardar %1: %2</translation>
    </message>
    <message>
        <source>an untitled scene</source>
        <translation>una escena sin título</translation>
    </message>
    <message>
        <source>Cannot recover the autosaved copy: %1</source>
        <translation>No se puede recuperar la copia guardada automáticamente: %1</translation>
    </message>
    <message>
        <source>Recovered the autosaved copy of %1</source>
        <translation>Recuperada la copia guardada automáticamente de %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Abrir...</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Abrir escena</translation>
    </message>
    <message>
        <source>Scenes (*.gltf *.glb *.glint.json);;All files (*)</source>
        <translation>Escenas (*.gltf *.glb *.glint.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importar...</translation>
    </message>
    <message>
        <source>Import into the scene</source>
        <translation>Importar en la escena</translation>
    </message>
    <message>
        <source>Scenes and models (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;All files (*)</source>
        <translation>Escenas y modelos (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Guardar &amp;como...</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Preferencias...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Eliminar</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>D&amp;uplicar</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Seleccionar &amp;todo</translation>
    </message>
    <message>
        <source>Select &amp;None</source>
        <translation>Seleccionar &amp;nada</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Paneles</translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation>&amp;Tema</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Oscuro</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>&amp;About Glint</source>
        <translation>&amp;Acerca de Glint</translation>
    </message>
    <message>
        <source>About Glint</source>
        <translation>Acerca de Glint</translation>
    </message>
    <message>
        <source>Glint %1: a scene editor with a built-in OpenGL 4.1 path tracer.</source>
        <translation>Glint %1: un editor de escenas con un trazador de caminos OpenGL 4.1 integrado.</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Acerca de &amp;Qt</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principal</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Barra de herramientas principal</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>View toolbar</source>
        <translation>Barra de herramientas de vista</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Vaciar la lista</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Deshacer %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rehacer %1</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>Export &amp;Image...</source>
        <translation>Exportar &amp;imagen...</translation>
    </message>
    <message>
        <source>Export A&amp;nimation...</source>
        <translation>Exportar a&amp;nimación...</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Abriendo %1</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importando %1</translation>
    </message>
    <message>
        <source>Recovering an untitled scene</source>
        <translation>Recuperando una escena sin título</translation>
    </message>
    <message>
        <source>Recovering %1</source>
        <translation>Recuperando %1</translation>
    </message>
    <message>
        <source>Cannot open %1:
%2</source>
        <translation>No se puede abrir %1:
%2</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Importación de %1 cancelada</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>Apertura de %1 cancelada</translation>
    </message>
    <message>
        <source>This display gives no OpenGL 4.1 core context, so the editor opens without its viewport; `glint render` renders headless (EGL).</source>
        <translation>Esta pantalla no ofrece un contexto OpenGL 4.1 core, así que el editor se abre sin su vista; `glint render` renderiza sin pantalla (EGL).</translation>
    </message>
    <message>
        <source>%1, %2, configuration: %3</source>
        <translation>%1, %2, configuración: %3</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes</source>
        <translation><numerusform>%n nodo</numerusform><numerusform>%n nodos</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n triangles</source>
        <translation><numerusform>%n triángulo</numerusform><numerusform>%n triángulos</numerusform></translation>
    </message>
    <message>
        <source>%1 (autosaved %2)</source>
        <translation>%1 (autoguardado %2)</translation>
    </message>
    <message>
        <source>Discard all autosaved copies</source>
        <translation>Descartar todas las copias autoguardadas</translation>
    </message>
    <message>
        <source>Nothing to recover</source>
        <translation>Nada que recuperar</translation>
    </message>
    <message>
        <source>Glint did not close normally: the copy of %1 autosaved at %2 is newer than the file.</source>
        <translation>Glint no se cerró con normalidad: la copia de %1 autoguardada a las %2 es más reciente que el archivo.</translation>
    </message>
    <message>
        <source>Glint did not close normally: unsaved work on %1 was autosaved at %2.</source>
        <translation>Glint no se cerró con normalidad: el trabajo sin guardar en %1 se autoguardó a las %2.</translation>
    </message>
    <message numerus="yes">
        <source>%n more in File &gt; Recover.</source>
        <translation><numerusform>%n más en Archivo &gt; Recuperar.</numerusform><numerusform>%n más en Archivo &gt; Recuperar.</numerusform></translation>
    </message>
    <message>
        <source>Re&amp;cover</source>
        <translation>Re&amp;cuperar</translation>
    </message>
    <message>
        <source>There are no meshes in %1: nothing to import.</source>
        <translation>%1 no contiene mallas: nada que importar.</translation>
    </message>
    <message>
        <source>%1 holds a mesh without any faces, so it cannot be imported.</source>
        <translation>%1 contiene una malla sin caras, así que no se puede importar.</translation>
    </message>
    <message>
        <source>%1 is in no format Glint imports (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</source>
        <translation>%1 no está en ningún formato que Glint importe (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</translation>
    </message>
    <message>
        <source>%1 ends too early: the file is damaged or was not copied completely.</source>
        <translation>%1 termina demasiado pronto: el archivo está dañado o no se copió completo.</translation>
    </message>
    <message>
        <source>%1 cannot be read.</source>
        <translation>%1 no se puede leer.</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 está vacío.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importar</translation>
    </message>
    <message>
        <source>Cannot import %1:
%2</source>
        <translation>No se puede importar %1:
%2</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiales</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Nueva escena</translation>
    </message>
    <message>
        <source>New from &amp;template</source>
        <translation>Nueva desde &amp;plantilla</translation>
    </message>
    <message>
        <source>%1 (autosaved %2, older than the file)</source>
        <translation>%1 (autoguardado %2, más antiguo que el archivo)</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialListModel</name>
    <message>
        <source>Material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message numerus="yes">
        <source>%n users</source>
        <translation><numerusform>%n usuario</numerusform><numerusform>%n usuarios</numerusform></translation>
    </message>
    <message>
        <source>%1: no node uses it (Delete unused removes it)</source>
        <translation>%1: ningún nodo lo usa (Eliminar no usados lo quita)</translation>
    </message>
    <message>
        <source>%1: drag it onto a node in the outliner or the viewport to assign it</source>
        <translation>%1: arrástrelo a un nodo del esquema o de la vista para asignarlo</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialPresets</name>
    <message>
        <source>Plastic</source>
        <translation>Plástico</translation>
    </message>
    <message>
        <source>Rough</source>
        <translation>Rugoso</translation>
    </message>
    <message>
        <source>Glossy (clear coat)</source>
        <translation>Brillante (laca)</translation>
    </message>
    <message>
        <source>Metal</source>
        <translation>Metal</translation>
    </message>
    <message>
        <source>Gold</source>
        <translation>Oro</translation>
    </message>
    <message>
        <source>Brushed metal</source>
        <translation>Metal cepillado</translation>
    </message>
    <message>
        <source>Glass</source>
        <translation>Vidrio</translation>
    </message>
    <message>
        <source>Frosted glass</source>
        <translation>Vidrio esmerilado</translation>
    </message>
    <message>
        <source>Emitter</source>
        <translation>Emisor</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialsPanel</name>
    <message>
        <source>Search materials</source>
        <translation>Buscar materiales</translation>
    </message>
    <message>
        <source>Material search</source>
        <translation>Búsqueda de materiales</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiales</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nuevo</translation>
    </message>
    <message>
        <source>A new material from a preset</source>
        <translation>Un material nuevo a partir de un preajuste</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <source>A copy of the selected material</source>
        <translation>Una copia del material seleccionado</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renombrar</translation>
    </message>
    <message>
        <source>Rename the selected material</source>
        <translation>Renombrar el material seleccionado</translation>
    </message>
    <message>
        <source>Delete unused</source>
        <translation>Eliminar no usados</translation>
    </message>
    <message>
        <source>Remove every material no node uses</source>
        <translation>Quita todo material que ningún nodo usa</translation>
    </message>
    <message>
        <source>Assign to selection</source>
        <translation>Asignar a la selección</translation>
    </message>
    <message>
        <source>Give the selected material to every selected shape and mesh (one undo step)</source>
        <translation>Asigna el material seleccionado a cada forma y malla seleccionadas (un solo paso de deshacer)</translation>
    </message>
    <message numerus="yes">
        <source>%n unused materials removed.</source>
        <translation><numerusform>%n material sin usar eliminado.</numerusform><numerusform>%n materiales sin usar eliminados.</numerusform></translation>
    </message>
    <message>
        <source>Select a material in the list first.</source>
        <translation>Seleccione primero un material en la lista.</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeKeyTracks</name>
    <message>
        <source>Node keys</source>
        <translation>Claves de nodos</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeNames</name>
    <message>
        <source>Sphere %1</source>
        <translation>Esfera %1</translation>
    </message>
    <message>
        <source>Quad %1</source>
        <translation>Quad %1</translation>
    </message>
    <message>
        <source>Disk %1</source>
        <translation>Disco %1</translation>
    </message>
    <message>
        <source>Box %1</source>
        <translation>Caja %1</translation>
    </message>
    <message>
        <source>Cylinder %1</source>
        <translation>Cilindro %1</translation>
    </message>
    <message>
        <source>Ground plane %1</source>
        <translation>Plano del suelo %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Nodo %1</translation>
    </message>
    <message>
        <source>Sun %1</source>
        <translation>Sol %1</translation>
    </message>
    <message>
        <source>Point light %1</source>
        <translation>Luz puntual %1</translation>
    </message>
    <message>
        <source>Spot light %1</source>
        <translation>Foco %1</translation>
    </message>
    <message>
        <source>Mesh %1</source>
        <translation>Malla %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Cámara %1</translation>
    </message>
    <message>
        <source>Area light %1</source>
        <translation>Luz de área %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerModel</name>
    <message>
        <source>Mesh</source>
        <translation>Malla</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Cámara</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Grupo</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Visible</translation>
    </message>
    <message>
        <source>Hidden</source>
        <translation>Oculto</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>%1 (%2; the file gives it no name)</source>
        <translation>%1 (%2; el archivo no le da nombre)</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerPanel</name>
    <message>
        <source>Filter by name</source>
        <translation>Filtrar por nombre</translation>
    </message>
    <message>
        <source>Outliner filter</source>
        <translation>Filtro del esquema</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
    <message>
        <source>Add a shape, light or camera</source>
        <translation>Añadir una forma, una luz o una cámara</translation>
    </message>
    <message>
        <source>Scene outliner</source>
        <translation>Esquema de la escena</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Esfera</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Caja</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Cuadrilátero</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Disco</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Cilindro</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Plano del suelo</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <source>Point light</source>
        <translation>Luz puntual</translation>
    </message>
    <message>
        <source>Spot light</source>
        <translation>Foco</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Sol</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Cámara</translation>
    </message>
    <message>
        <source>Empty group</source>
        <translation>Grupo vacío</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renombrar</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Area rectangle</source>
        <translation>Rectángulo de área</translation>
    </message>
    <message>
        <source>Area disk</source>
        <translation>Disco de área</translation>
    </message>
    <message>
        <source>Area sphere</source>
        <translation>Esfera de área</translation>
    </message>
    <message>
        <source>Portal pair</source>
        <translation>Par de portales</translation>
    </message>
    <message>
        <source>Studio environment</source>
        <translation>Entorno de estudio</translation>
    </message>
</context>
<context>
    <name>glint::editor::PortalEdits</name>
    <message>
        <source>Add Portal Pair</source>
        <translation>Añadir par de portales</translation>
    </message>
    <message>
        <source>Portal A</source>
        <translation>Portal A</translation>
    </message>
    <message>
        <source>Portal B</source>
        <translation>Portal B</translation>
    </message>
    <message>
        <source>Only a quad can be a portal.</source>
        <translation>Solo un cuadrilátero puede ser un portal.</translation>
    </message>
    <message>
        <source>A portal cannot lead to itself.</source>
        <translation>Un portal no puede llevar a sí mismo.</translation>
    </message>
    <message>
        <source>A portal can only lead to another quad.</source>
        <translation>Un portal solo puede llevar a otro cuadrilátero.</translation>
    </message>
    <message>
        <source>Link Portals</source>
        <translation>Enlazar portales</translation>
    </message>
    <message>
        <source>Unlink Portal</source>
        <translation>Desenlazar portal</translation>
    </message>
</context>
<context>
    <name>glint::editor::Preferences</name>
    <message>
        <source>System language</source>
        <translation>Idioma del sistema</translation>
    </message>
</context>
<context>
    <name>glint::editor::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Preferencias</translation>
    </message>
    <message>
        <source>General</source>
        <translation>General</translation>
    </message>
    <message>
        <source>Keymap</source>
        <translation>Atajos</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Oscuro</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Tema</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Desactivado</translation>
    </message>
    <message>
        <source>Autosave interval</source>
        <translation>Intervalo de guardado automático</translation>
    </message>
    <message>
        <source>Autosave every</source>
        <translation>Guardado automático cada</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Comando</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Atajo</translation>
    </message>
    <message>
        <source>Shortcut for %1</source>
        <translation>Atajo para %1</translation>
    </message>
    <message>
        <source>Shortcut conflict</source>
        <translation>Conflicto de atajos</translation>
    </message>
    <message>
        <source>%1 is used by both "%2" and "%3".</source>
        <translation>%1 lo usan tanto "%2" como "%3".</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Sin límite</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Muestras de la vista</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here (renders use the Scene panel's samples)</source>
        <translation>La vista deja de añadir muestras por píxel aquí (los renders usan las muestras del panel Escena)</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Predeterminado</translation>
    </message>
    <message>
        <source>Reset all to defaults</source>
        <translation>Restablecer todo a lo predeterminado</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertiesPanel</name>
    <message>
        <source>Scene settings</source>
        <translation>Ajustes de la escena</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propiedades</translation>
    </message>
    <message>
        <source>Select a node in the outliner or the viewport to edit it.</source>
        <translation>Seleccione un nodo en el esquema o en la vista para editarlo.</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyEdits</name>
    <message>
        <source>Edit %1 nodes</source>
        <translation>Editar %1 nodos</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyForm</name>
    <message>
        <source>Texture %1</source>
        <translation>Textura %1</translation>
    </message>
    <message>
        <source>%1 thumbnail</source>
        <translation>Miniatura de %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguna)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>sin nombre</translation>
    </message>
    <message>
        <source>Material: %1</source>
        <translation>Material: %1</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>Color base</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Opacidad</translation>
    </message>
    <message>
        <source>Base colour texture</source>
        <translation>Textura de color base</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Metálico</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rugosidad</translation>
    </message>
    <message>
        <source>Metallic-roughness texture</source>
        <translation>Textura metálico-rugosidad</translation>
    </message>
    <message>
        <source>Normal texture</source>
        <translation>Textura de normales</translation>
    </message>
    <message>
        <source>Occlusion texture</source>
        <translation>Textura de oclusión</translation>
    </message>
    <message>
        <source>Emission</source>
        <translation>Emisión</translation>
    </message>
    <message>
        <source>Emission strength</source>
        <translation>Intensidad de emisión</translation>
    </message>
    <message>
        <source>Emission texture</source>
        <translation>Textura de emisión</translation>
    </message>
    <message>
        <source>Specular</source>
        <translation>Especular</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>Color especular</translation>
    </message>
    <message>
        <source>Specular texture</source>
        <translation>Textura especular</translation>
    </message>
    <message>
        <source>Specular colour texture</source>
        <translation>Textura de color especular</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>Transmisión</translation>
    </message>
    <message>
        <source>Transmission texture</source>
        <translation>Textura de transmisión</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>Índice de refracción</translation>
    </message>
    <message>
        <source>Thickness</source>
        <translation>Grosor</translation>
    </message>
    <message>
        <source>Thickness texture</source>
        <translation>Textura de grosor</translation>
    </message>
    <message>
        <source>Attenuation distance (m)</source>
        <translation>Distancia de atenuación (m)</translation>
    </message>
    <message>
        <source>Attenuation colour</source>
        <translation>Color de atenuación</translation>
    </message>
    <message>
        <source>Alpha mode</source>
        <translation>Modo alfa</translation>
    </message>
    <message>
        <source>Opaque</source>
        <translation>Opaco</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Máscara</translation>
    </message>
    <message>
        <source>Blend</source>
        <translation>Mezcla</translation>
    </message>
    <message>
        <source>Alpha cutoff</source>
        <translation>Umbral alfa</translation>
    </message>
    <message>
        <source>Double sided</source>
        <translation>Doble cara</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Nodo</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Visible</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformación</translation>
    </message>
    <message>
        <source>Position %1</source>
        <translation>Posición %1</translation>
    </message>
    <message>
        <source>Rotation %1 (degrees)</source>
        <translation>Rotación %1 (grados)</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <translation>Escala %1</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Esfera</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Cuadrilátero</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Disco</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Caja</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Cilindro</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Plano del suelo</translation>
    </message>
    <message>
        <source>Radius (m)</source>
        <translation>Radio (m)</translation>
    </message>
    <message>
        <source>Height (m)</source>
        <translation>Altura (m)</translation>
    </message>
    <message>
        <source>Size %1 (m)</source>
        <translation>Tamaño %1 (m)</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Sol</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Puntual</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Foco</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Color</translation>
    </message>
    <message>
        <source>lux</source>
        <translation>lux</translation>
    </message>
    <message>
        <source>cd</source>
        <translation>cd</translation>
    </message>
    <message>
        <source>Blender units</source>
        <translation>unidades de Blender</translation>
    </message>
    <message>
        <source>raw units</source>
        <translation>unidades sin convertir</translation>
    </message>
    <message>
        <source>Intensity (%1, %2)</source>
        <translation>Intensidad (%1, %2)</translation>
    </message>
    <message>
        <source>Range (m, 0 = infinite)</source>
        <translation>Alcance (m, 0 = infinito)</translation>
    </message>
    <message>
        <source>Inner cone (degrees)</source>
        <translation>Cono interior (grados)</translation>
    </message>
    <message>
        <source>Outer cone (degrees)</source>
        <translation>Cono exterior (grados)</translation>
    </message>
    <message>
        <source>Sun angular diameter (degrees)</source>
        <translation>Diámetro angular del sol (grados)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Cámara</translation>
    </message>
    <message>
        <source>Projection</source>
        <translation>Proyección</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspectiva</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <translation>Ortográfica</translation>
    </message>
    <message>
        <source>Vertical field of view (degrees)</source>
        <translation>Campo de visión vertical (grados)</translation>
    </message>
    <message>
        <source>Lens radius (m)</source>
        <translation>Radio de la lente (m)</translation>
    </message>
    <message>
        <source>Focus distance (m)</source>
        <translation>Distancia de enfoque (m)</translation>
    </message>
    <message>
        <source>Exposure (EV)</source>
        <translation>Exposición (EV)</translation>
    </message>
    <message>
        <source>Near clip (m)</source>
        <translation>Plano de recorte cercano (m)</translation>
    </message>
    <message>
        <source>Active camera</source>
        <translation>Cámara activa</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Entorno</translation>
    </message>
    <message>
        <source>HDR file</source>
        <translation>Archivo HDR</translation>
    </message>
    <message>
        <source>Colour (no file)</source>
        <translation>Color (sin archivo)</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensidad</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>Rotación (grados)</translation>
    </message>
    <message>
        <source>Render settings</source>
        <translation>Ajustes de render</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configuración</translation>
    </message>
    <message>
        <source>Width (px)</source>
        <translation>Ancho (px)</translation>
    </message>
    <message>
        <source>Height (px)</source>
        <translation>Alto (px)</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Muestras por píxel</translation>
    </message>
    <message>
        <source>Bounces</source>
        <translation>Rebotes</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Semilla</translation>
    </message>
    <message>
        <source>Tonemapper</source>
        <translation>Mapeo de tonos</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Ninguno</translation>
    </message>
    <message>
        <source>ACES (fitted)</source>
        <translation>ACES (ajustado)</translation>
    </message>
    <message>
        <source>Khronos PBR Neutral</source>
        <translation>Khronos PBR Neutral</translation>
    </message>
    <message>
        <source>Radiance clamp (0 = off)</source>
        <translation>Límite de radiancia (0 = desactivado)</translation>
    </message>
    <message>
        <source>Light units</source>
        <translation>Unidades de luz</translation>
    </message>
    <message>
        <source>Blender (W = lm / 683)</source>
        <translation>Blender (W = lm / 683)</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Sin convertir</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>Choose an HDR environment file</source>
        <translation>Elegir un archivo de entorno HDR</translation>
    </message>
    <message>
        <source>Environment map</source>
        <translation>Mapa de entorno</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>Imágenes HDR (*.hdr *.exr);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Camera and timeline</source>
        <translation>Cámara y línea de tiempo</translation>
    </message>
    <message>
        <source>(the first camera)</source>
        <translation>(la primera cámara)</translation>
    </message>
    <message>
        <source>Timeline start (s)</source>
        <translation>Inicio de la línea de tiempo (s)</translation>
    </message>
    <message>
        <source>Timeline end (s, 0 = the animation's)</source>
        <translation>Fin de la línea de tiempo (s, 0 = la de la animación)</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Fotogramas por segundo</translation>
    </message>
    <message>
        <source>Frames per second must be a positive number or a ratio such as 24000/1001, not "%1".</source>
        <translation>Los fotogramas por segundo deben ser un número positivo o una razón como 24000/1001, no "%1".</translation>
    </message>
    <message>
        <source>Real-time reconstruction</source>
        <translation>Reconstrucción en tiempo real</translation>
    </message>
    <message>
        <source>TAA blend (current frame)</source>
        <translation>Mezcla TAA (fotograma actual)</translation>
    </message>
    <message>
        <source>TAA clip box (std. deviations)</source>
        <translation>Caja de recorte TAA (desviaciones típ.)</translation>
    </message>
    <message>
        <source>TAA perceptual blend</source>
        <translation>Mezcla perceptual TAA</translation>
    </message>
    <message>
        <source>SVGF a-trous iterations</source>
        <translation>Iteraciones à-trous de SVGF</translation>
    </message>
    <message>
        <source>SVGF temporal alpha</source>
        <translation>Alfa temporal de SVGF</translation>
    </message>
    <message>
        <source>SVGF moments alpha</source>
        <translation>Alfa de momentos de SVGF</translation>
    </message>
    <message>
        <source>SVGF luminance sigma</source>
        <translation>Sigma de luminancia de SVGF</translation>
    </message>
    <message>
        <source>SVGF normal sigma (exponent)</source>
        <translation>Sigma de normales de SVGF (exponente)</translation>
    </message>
    <message>
        <source>SVGF depth sigma</source>
        <translation>Sigma de profundidad de SVGF</translation>
    </message>
    <message>
        <source>SVGF firefly ratio</source>
        <translation>Razón de luciérnagas de SVGF</translation>
    </message>
    <message>
        <source>TAA history clipping</source>
        <translation>Recorte del historial TAA</translation>
    </message>
    <message>
        <source>Variance clip (YCoCg)</source>
        <translation>Recorte por varianza (YCoCg)</translation>
    </message>
    <message>
        <source>Min/max clamp</source>
        <translation>Limitación mín/máx</translation>
    </message>
    <message>
        <source>None (ghosts)</source>
        <translation>Ninguno (fantasmas)</translation>
    </message>
    <message>
        <source>"%1" is relative, but the scene has no folder yet: choose the file with Browse, or save the scene first.</source>
        <translation>"%1" es relativo, pero la escena aún no tiene carpeta: elige el archivo con Examinar o guarda primero la escena.</translation>
    </message>
    <message>
        <source>Cannot read the environment image %1. Choose it again with Browse, or clear the field to use the colour below.</source>
        <translation>No se puede leer la imagen de entorno %1. Vuelve a elegirla con Examinar o vacía el campo para usar el color de abajo.</translation>
    </message>
    <message>
        <source>Environment image status</source>
        <translation>Estado de la imagen de entorno</translation>
    </message>
    <message>
        <source>An infinite plane: the node's y = 0, facing +Y; move and turn it with the transform. It has no size. In the glTF file other programs (Blender) get a 200 m square in its place.</source>
        <translation>Un plano infinito: y = 0 del nodo, orientado hacia +Y; muévelo y gíralo con la transformación. No tiene tamaño. En el archivo glTF, otros programas (Blender) reciben en su lugar un cuadrado de 200 m.</translation>
    </message>
    <message>
        <source>Half height (m)</source>
        <translation>Semialtura (m)</translation>
    </message>
    <message>
        <source>AgX</source>
        <translation>AgX</translation>
    </message>
    <message>
        <source>Reinhard (extended)</source>
        <translation>Reinhard (extendido)</translation>
    </message>
    <message>
        <source>Hable (Uncharted 2)</source>
        <translation>Hable (Uncharted 2)</translation>
    </message>
    <message>
        <source>Bloom strength (0 = off)</source>
        <translation>Intensidad del bloom (0 = desactivado)</translation>
    </message>
    <message>
        <source>Bloom radius (of the height)</source>
        <translation>Radio del bloom (respecto a la altura)</translation>
    </message>
    <message>
        <source>Edit sampler</source>
        <translation>Editar muestreador</translation>
    </message>
    <message>
        <source>Load texture</source>
        <translation>Cargar textura</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</source>
        <translation>Imágenes (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Cargar…</translation>
    </message>
    <message>
        <source>Load an image file (PNG, JPEG, EXR, HDR, TIFF) into this slot</source>
        <translation>Cargar un archivo de imagen (PNG, JPEG, EXR, HDR, TIFF) en esta ranura</translation>
    </message>
    <message>
        <source>Load %1</source>
        <translation>Cargar %1</translation>
    </message>
    <message>
        <source>UV set</source>
        <translation>Conjunto UV</translation>
    </message>
    <message>
        <source>Repeat</source>
        <translation>Repetir</translation>
    </message>
    <message>
        <source>Clamp to edge</source>
        <translation>Fijar al borde</translation>
    </message>
    <message>
        <source>Mirrored repeat</source>
        <translation>Repetición reflejada</translation>
    </message>
    <message>
        <source>Wrap U</source>
        <translation>Repetición U</translation>
    </message>
    <message>
        <source>Wrap V</source>
        <translation>Repetición V</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filtro</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Nearest</source>
        <translation>Más cercano</translation>
    </message>
    <message>
        <source>Offset U</source>
        <translation>Desplazamiento U</translation>
    </message>
    <message>
        <source>Offset V</source>
        <translation>Desplazamiento V</translation>
    </message>
    <message>
        <source>Scale U</source>
        <translation>Escala U</translation>
    </message>
    <message>
        <source>Scale V</source>
        <translation>Escala V</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiales</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Editar</translation>
    </message>
    <message>
        <source>Show this primitive's material below</source>
        <translation>Mostrar abajo el material de esta primitiva</translation>
    </message>
    <message numerus="yes">
        <source>Primitive %1 (%n triangles)</source>
        <translation><numerusform>Primitiva %1 (%n triángulo)</numerusform><numerusform>Primitiva %1 (%n triángulos)</numerusform></translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>(default)</source>
        <translation>(predeterminado)</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>Motion blur shutter (frames, 0 = off)</source>
        <translation>Obturador de desenfoque de movimiento (fotogramas, 0 = apagado)</translation>
    </message>
    <message>
        <source>Rectangle</source>
        <translation>Rectángulo</translation>
    </message>
    <message>
        <source>Power (W)</source>
        <translation>Potencia (W)</translation>
    </message>
    <message>
        <source>Size X (m)</source>
        <translation>Tamaño X (m)</translation>
    </message>
    <message>
        <source>Size Y (m)</source>
        <translation>Tamaño Y (m)</translation>
    </message>
    <message>
        <source>Diameter (m)</source>
        <translation>Diámetro (m)</translation>
    </message>
    <message>
        <source>Emits its power evenly from the front face (the light's -Z) of the rectangle or disk, or the outside of the sphere; in the glTF file other programs get an emissive mesh.</source>
        <translation>Emite su potencia uniformemente desde la cara frontal (el -Z de la luz) del rectángulo o el disco, o desde el exterior de la esfera; en el archivo glTF los demás programas reciben una malla emisiva.</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Área</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Muestras de la vista</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Sin límite</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here; renders use the samples per pixel above</source>
        <translation>La vista deja de añadir muestras por píxel aquí; los renders usan las muestras por píxel de arriba</translation>
    </message>
    <message>
        <source>Rendering</source>
        <translation>Render</translation>
    </message>
    <message>
        <source>Noise threshold (adaptive sampling, 0 = off)</source>
        <translation>Umbral de ruido (muestreo adaptativo, 0 = desactivado)</translation>
    </message>
    <message>
        <source>Adaptive minimum samples (0 = automatic)</source>
        <translation>Muestras mínimas adaptativas (0 = automático)</translation>
    </message>
    <message>
        <source>Scatter anisotropy</source>
        <translation>Anisotropía de dispersión</translation>
    </message>
    <message>
        <source>Scatter colour</source>
        <translation>Color de dispersión</translation>
    </message>
    <message>
        <source>Fog</source>
        <translation>Niebla</translation>
    </message>
    <message>
        <source>Density (1/m)</source>
        <translation>Densidad (1/m)</translation>
    </message>
    <message>
        <source>Anisotropy</source>
        <translation>Anisotropía</translation>
    </message>
    <message>
        <source>Height falloff (1/m)</source>
        <translation>Atenuación con la altura (1/m)</translation>
    </message>
    <message>
        <source>Base height (m)</source>
        <translation>Altura base (m)</translation>
    </message>
    <message>
        <source>node %1, deleted</source>
        <translation>nodo %1, eliminado</translation>
    </message>
    <message>
        <source>Not paired: the other side does not lead back here, so this quad is an ordinary surface. Choose a quad to pair them again.</source>
        <translation>Sin emparejar: el otro lado no lleva de vuelta aquí, así que este cuadrilátero es una superficie normal. Elige un cuadrilátero para emparejarlos de nuevo.</translation>
    </message>
    <message>
        <source>What enters this quad leaves the quad chosen here, and the other way round.</source>
        <translation>Lo que entra en este cuadrilátero sale del cuadrilátero elegido aquí, y al revés.</translation>
    </message>
    <message>
        <source>Portal to</source>
        <translation>Portal hacia</translation>
    </message>
    <message>
        <source>Adaptive goal</source>
        <translation>Objetivo adaptativo</translation>
    </message>
    <message>
        <source>Even noise (as Cycles)</source>
        <translation>Ruido uniforme (como Cycles)</translation>
    </message>
    <message>
        <source>Least mean error</source>
        <translation>Error medio mínimo</translation>
    </message>
    <message>
        <source>Sample blocks (pixels sharing a sequence)</source>
        <translation>Bloques de muestras (píxeles que comparten una secuencia)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Desactivado</translation>
    </message>
</context>
<context>
    <name>glint::editor::RecoveryBar</name>
    <message>
        <source>Recover unsaved work</source>
        <translation>Recuperar el trabajo sin guardar</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Recuperar</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Descartar</translation>
    </message>
    <message>
        <source>Delete the autosaved copy</source>
        <translation>Eliminar la copia autoguardada</translation>
    </message>
    <message>
        <source>Later (File &gt; Recover keeps it)</source>
        <translation>Más tarde (queda en Archivo &gt; Recuperar)</translation>
    </message>
    <message>
        <source>Hide</source>
        <translation>Ocultar</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderHost</name>
    <message>
        <source>Preparing the scene</source>
        <translation>Preparando la escena</translation>
    </message>
    <message>
        <source>building mesh BVHs</source>
        <translation>construyendo los BVH de las mallas</translation>
    </message>
    <message>
        <source>decoding textures</source>
        <translation>decodificando texturas</translation>
    </message>
    <message>
        <source>loading the environment</source>
        <translation>cargando el entorno</translation>
    </message>
    <message>
        <source>packing the scene</source>
        <translation>empaquetando la escena</translation>
    </message>
    <message>
        <source>building the click picker</source>
        <translation>construyendo el selector de clic</translation>
    </message>
    <message>
        <source>Preparing the scene: %1 %2/%3</source>
        <translation>Preparando la escena: %1 %2/%3</translation>
    </message>
    <message>
        <source>Preparing the scene: %1</source>
        <translation>Preparando la escena: %1</translation>
    </message>
    <message>
        <source>Nothing in the scene emits light, so the path-traced image is black: add a light (Add &gt; Light &gt; Studio environment lights any model) or an emissive material, or give the environment a colour or an image (Scene tab).</source>
        <translation>Nada en la escena emite luz, así que la imagen trazada es negra: añade una luz (Añadir &gt; Luz &gt; Entorno de estudio ilumina cualquier modelo) o un material emisivo, o da al entorno un color o una imagen (pestaña Escena).</translation>
    </message>
    <message>
        <source>Only emissive textures give light in this scene, so most of the path-traced image is dark: add a light (Add &gt; Light &gt; Studio environment lights any model), or give the environment a colour or an image (Scene tab).</source>
        <translation>En esta escena solo las texturas emisivas dan luz, así que la mayor parte de la imagen trazada es oscura: añade una luz (Añadir &gt; Luz &gt; Entorno de estudio ilumina cualquier modelo) o da al entorno un color o una imagen (pestaña Escena).</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderView</name>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>Pixel %1, %2
R %3  G %4  B %5 (linear)</source>
        <translation>Píxel %1, %2
R %3  G %4  B %5 (lineal)</translation>
    </message>
</context>
<context>
    <name>glint::editor::SceneLoader</name>
    <message>
        <source>reading the glTF file</source>
        <translation>leyendo el archivo glTF</translation>
    </message>
    <message>
        <source>running the importer</source>
        <translation>ejecutando el importador</translation>
    </message>
</context>
<context>
    <name>glint::editor::SceneTemplates</name>
    <message>
        <source>Studio</source>
        <translation>Estudio</translation>
    </message>
    <message>
        <source>Empty</source>
        <translation>Vacía</translation>
    </message>
    <message>
        <source>Sun and sky</source>
        <translation>Sol y cielo</translation>
    </message>
    <message>
        <source>Cornell box</source>
        <translation>Caja de Cornell</translation>
    </message>
    <message>
        <source>Cornell box in fog</source>
        <translation>Caja de Cornell en la niebla</translation>
    </message>
    <message>
        <source>Portals</source>
        <translation>Portales</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimeRuler</name>
    <message>
        <source>Time ruler</source>
        <translation>Regla de tiempo</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimelinePanel</name>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>Path camera</source>
        <translation>Cámara de trayectoria</translation>
    </message>
    <message>
        <source>  %1 s  (frame %2)</source>
        <translation>  %1 s  (fotograma %2)</translation>
    </message>
    <message>
        <source>Add key</source>
        <translation>Añadir clave</translation>
    </message>
    <message>
        <source>Add a camera-path key from the current view at the current time</source>
        <translation>Añade una clave de trayectoria de cámara desde la vista actual en el instante actual</translation>
    </message>
    <message>
        <source>Delete key</source>
        <translation>Eliminar clave</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Bucle</translation>
    </message>
    <message>
        <source>Constant speed</source>
        <translation>Velocidad constante</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>FOV</source>
        <translation>Campo de visión</translation>
    </message>
    <message>
        <source>Focus</source>
        <translation>Enfoque</translation>
    </message>
    <message>
        <source>Lens</source>
        <translation>Lente</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <source>Key %1</source>
        <translation>Clave %1</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Clave de transformación</translation>
    </message>
    <message>
        <source>Key the selected nodes' position, rotation and scale at the current time (K)</source>
        <translation>Inserta una clave de posición, rotación y escala de los nodos seleccionados en el instante actual (K)</translation>
    </message>
    <message>
        <source>Copy key</source>
        <translation>Copiar clave</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Pegar clave</translation>
    </message>
    <message>
        <source>Key the selected nodes at the current time with the copied key's transform</source>
        <translation>Inserta una clave en los nodos seleccionados en el instante actual con la transformación de la clave copiada</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>Interpolación</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Escalón</translation>
    </message>
    <message>
        <source>Cubic</source>
        <translation>Cúbica</translation>
    </message>
    <message>
        <source>Auto key</source>
        <translation>Clave automática</translation>
    </message>
    <message>
        <source>Key every moved, turned or scaled node at the current time (nodes with keys are always keyed)</source>
        <translation>Insertar una clave en cada nodo movido, girado o escalado en el tiempo actual (los nodos con claves siempre reciben una)</translation>
    </message>
</context>
<context>
    <name>glint::editor::Viewport</name>
    <message>
        <source>Path traced</source>
        <translation>Trazado de caminos</translation>
    </message>
    <message>
        <source>Solid</source>
        <translation>Sólido</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>Estructura de alambre</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normales</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <source>Ambient occlusion</source>
        <translation>Oclusión ambiental</translation>
    </message>
    <message>
        <source>Motion vectors</source>
        <translation>Vectores de movimiento</translation>
    </message>
    <message>
        <source>Variance</source>
        <translation>Varianza</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Profundidad</translation>
    </message>
    <message>
        <source>BVH instance boxes</source>
        <translation>Cajas BVH de instancias</translation>
    </message>
    <message>
        <source>BVH traversal cost (heat map)</source>
        <translation>Coste de recorrido BVH (mapa de calor)</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Mover</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Rotar</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Escalar</translation>
    </message>
    <message>
        <source>Frame selection</source>
        <translation>Encuadrar selección</translation>
    </message>
    <message>
        <source>Make scene camera from view</source>
        <translation>Crear cámara de escena desde la vista</translation>
    </message>
    <message>
        <source>Look through selected camera</source>
        <translation>Ver a través de la cámara seleccionada</translation>
    </message>
    <message>
        <source>Snap (Ctrl inverts while dragging)</source>
        <translation>Ajuste (Ctrl invierte al arrastrar)</translation>
    </message>
    <message>
        <source>Pixel inspector</source>
        <translation>Inspector de píxeles</translation>
    </message>
    <message>
        <source>Take snapshot A</source>
        <translation>Tomar instantánea A</translation>
    </message>
    <message>
        <source>Set render region</source>
        <translation>Fijar región de render</translation>
    </message>
    <message>
        <source>Drag a rectangle: the path tracer renders only inside it</source>
        <translation>Arrastre un rectángulo: el trazador de caminos solo renderiza dentro</translation>
    </message>
    <message>
        <source>Clear render region</source>
        <translation>Borrar región de render</translation>
    </message>
    <message>
        <source>Compare A | B</source>
        <translation>Comparar A | B</translation>
    </message>
    <message>
        <source>Pick focus distance</source>
        <translation>Elegir distancia de enfoque</translation>
    </message>
    <message>
        <source>Click a surface: the camera looked through focuses at its depth</source>
        <translation>Haga clic en una superficie: la cámara a través de la que mira enfoca a su profundidad</translation>
    </message>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>Elegir el enfoque funciona a través de una cámara de la escena: seleccione una y mire a través de ella (0) primero.</translation>
    </message>
    <message>
        <source>Click the surface to focus on (Esc cancels).</source>
        <translation>Haga clic en la superficie que enfocar (Esc cancela).</translation>
    </message>
    <message>
        <source>Pause viewport rendering</source>
        <translation>Pausar el render de la vista</translation>
    </message>
    <message>
        <source>Stop adding samples; edits are still shown at full resolution</source>
        <translation>Deja de añadir muestras; las ediciones se siguen mostrando a resolución completa</translation>
    </message>
    <message>
        <source>Denoise still image</source>
        <translation>Eliminar ruido de la imagen fija</translation>
    </message>
    <message>
        <source>Filter the accumulated image while it converges (off: the raw running mean; renders are never filtered)</source>
        <translation>Filtrar la imagen acumulada mientras converge (desactivado: la media sin filtrar; los renders nunca se filtran)</translation>
    </message>
    <message>
        <source>coarse (1/%1 resolution)</source>
        <translation>aproximada (resolución 1/%1)</translation>
    </message>
    <message>
        <source>refining to full resolution: %1%</source>
        <translation>refinando a resolución completa: %1%</translation>
    </message>
    <message>
        <source>%1 / %2 spp</source>
        <translation>%1 / %2 spp</translation>
    </message>
    <message>
        <source>%1 spp</source>
        <translation>%1 spp</translation>
    </message>
    <message>
        <source>%1 spp, converged (viewport sample cap)</source>
        <translation>%1 spp, convergida (límite de muestras de la vista)</translation>
    </message>
    <message>
        <source>%1 spp, paused</source>
        <translation>%1 spp, en pausa</translation>
    </message>
    <message>
        <source>%1  |  %2 ms/frame</source>
        <translation>%1  |  %2 ms/fotograma</translation>
    </message>
    <message>
        <source>Local axes</source>
        <translation>Ejes locales</translation>
    </message>
    <message>
        <source>Move and rotate along the selected node's own axes (off: the world's)</source>
        <translation>Mover y girar según los ejes propios del nodo seleccionado (apagado: los del mundo)</translation>
    </message>
    <message>
        <source>up to %1 spp, converged (noise threshold)</source>
        <translation>hasta %1 spp, convergida (umbral de ruido)</translation>
    </message>
    <message>
        <source>%1, %2% converged</source>
        <translation>%1, %2% convergido</translation>
    </message>
</context>
</TS>