<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>FocusPick</name>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>Fokuswahl wirkt durch eine Szenenkamera: wählen Sie zuerst eine aus und schauen Sie hindurch (0).</translation>
    </message>
    <message>
        <source>Pick focus: %1 follows its camera path, whose keys set the focus; edit them in the timeline.</source>
        <translation>Fokuswahl: %1 folgt seinem Kamerapfad, dessen Schlüssel den Fokus setzen; bearbeiten Sie sie in der Zeitleiste.</translation>
    </message>
    <message>
        <source>Pick focus: nothing under the cursor, the focus distance is unchanged.</source>
        <translation>Fokuswahl: nichts unter dem Mauszeiger, der Fokusabstand bleibt.</translation>
    </message>
    <message>
        <source>Pick focus: the surface is behind the camera, the focus distance is unchanged.</source>
        <translation>Fokuswahl: die Fläche liegt hinter der Kamera, der Fokusabstand bleibt.</translation>
    </message>
    <message>
        <source>Focus distance of %1: %2 m (%3)</source>
        <translation>Fokusabstand von %1: %2 m (%3)</translation>
    </message>
</context>
<context>
    <name>OverlayPainter</name>
    <message>
        <source>BVH nodes + primitives</source>
        <translation>BVH-Knoten + Primitive</translation>
    </message>
</context>
<context>
    <name>glint::editor</name>
    <message>
        <source>%1 cannot be read as an image: %2</source>
        <translation>%1 kann nicht als Bild gelesen werden: %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted: %2</source>
        <translation>%1 kann nicht umgewandelt werden: %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted to PNG: %2</source>
        <translation>%1 kann nicht in PNG umgewandelt werden: %2</translation>
    </message>
    <message>
        <source>The material no longer exists.</source>
        <translation>Das Material existiert nicht mehr.</translation>
    </message>
    <message>
        <source>A material needs a name.</source>
        <translation>Ein Material braucht einen Namen.</translation>
    </message>
    <message>
        <source>Delete unused materials</source>
        <translation>Unbenutzte Materialien löschen</translation>
    </message>
    <message>
        <source>Select a shape or a mesh to assign the material to.</source>
        <translation>Eine Form oder ein Netz auswählen, dem das Material zugewiesen wird.</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Material zuweisen</translation>
    </message>
    <message>
        <source>The mesh no longer exists.</source>
        <translation>Das Netz existiert nicht mehr.</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 existiert nicht.</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 ist leer.</translation>
    </message>
    <message>
        <source>Load texture %1</source>
        <translation>Textur %1 laden</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Transformation verschlüsseln</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Schlüssel einfügen</translation>
    </message>
</context>
<context>
    <name>glint::editor::Autosave</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>Der Ordner für automatisches Speichern %1 kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>glint::editor::ColorField</name>
    <message>
        <source>Choose a colour</source>
        <translation>Farbe wählen</translation>
    </message>
    <message>
        <source>%1 (sRGB); stored linear: %2, %3, %4</source>
        <translation>%1 (sRGB); linear gespeichert: %2, %3, %4</translation>
    </message>
</context>
<context>
    <name>glint::editor::CommandLabels</name>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Show/hide</source>
        <translation>Ein-/ausblenden</translation>
    </message>
    <message>
        <source>Edit component</source>
        <translation>Komponente bearbeiten</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Neu zuordnen</translation>
    </message>
    <message>
        <source>Edit settings</source>
        <translation>Einstellungen bearbeiten</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Add camera key</source>
        <translation>Kameraschlüssel hinzufügen</translation>
    </message>
    <message>
        <source>Edit camera key</source>
        <translation>Kameraschlüssel bearbeiten</translation>
    </message>
    <message>
        <source>Move camera key</source>
        <translation>Kameraschlüssel verschieben</translation>
    </message>
    <message>
        <source>Remove camera key</source>
        <translation>Kameraschlüssel entfernen</translation>
    </message>
    <message>
        <source>Camera path mode</source>
        <translation>Kamerapfad-Modus</translation>
    </message>
    <message>
        <source>mesh</source>
        <translation>Netz</translation>
    </message>
    <message>
        <source>material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>texture</source>
        <translation>Textur</translation>
    </message>
    <message>
        <source>image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>Sampler</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>%1 entfernen</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>%1 duplizieren</translation>
    </message>
    <message>
        <source>Edit %1</source>
        <translation>%1 bearbeiten</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Skalieren</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformation</translation>
    </message>
    <message>
        <source>Change configuration</source>
        <translation>Konfiguration ändern</translation>
    </message>
    <message>
        <source>Change image size</source>
        <translation>Bildgröße ändern</translation>
    </message>
    <message>
        <source>Change samples per pixel</source>
        <translation>Samples pro Pixel ändern</translation>
    </message>
    <message>
        <source>Change bounces</source>
        <translation>Abprallungen ändern</translation>
    </message>
    <message>
        <source>Change seed</source>
        <translation>Startwert ändern</translation>
    </message>
    <message>
        <source>Change exposure</source>
        <translation>Belichtung ändern</translation>
    </message>
    <message>
        <source>Change tonemapper</source>
        <translation>Tonemapper ändern</translation>
    </message>
    <message>
        <source>Change radiance clamp</source>
        <translation>Radianzbegrenzung ändern</translation>
    </message>
    <message>
        <source>Change TAA settings</source>
        <translation>TAA-Einstellungen ändern</translation>
    </message>
    <message>
        <source>Change SVGF settings</source>
        <translation>SVGF-Einstellungen ändern</translation>
    </message>
    <message>
        <source>Change environment image</source>
        <translation>Umgebungsbild ändern</translation>
    </message>
    <message>
        <source>Change environment colour</source>
        <translation>Umgebungsfarbe ändern</translation>
    </message>
    <message>
        <source>Change environment intensity</source>
        <translation>Umgebungsintensität ändern</translation>
    </message>
    <message>
        <source>Rotate environment</source>
        <translation>Umgebung drehen</translation>
    </message>
    <message>
        <source>Change active camera</source>
        <translation>Aktive Kamera ändern</translation>
    </message>
    <message>
        <source>Change timeline range</source>
        <translation>Zeitleistenbereich ändern</translation>
    </message>
    <message>
        <source>Change frame rate</source>
        <translation>Bildrate ändern</translation>
    </message>
    <message>
        <source>Change output</source>
        <translation>Ausgabe ändern</translation>
    </message>
    <message>
        <source>Change light units</source>
        <translation>Lichteinheiten ändern</translation>
    </message>
    <message>
        <source>Change light type</source>
        <translation>Lichttyp ändern</translation>
    </message>
    <message>
        <source>Change light colour</source>
        <translation>Lichtfarbe ändern</translation>
    </message>
    <message>
        <source>Change light intensity</source>
        <translation>Lichtintensität ändern</translation>
    </message>
    <message>
        <source>Change light range</source>
        <translation>Lichtreichweite ändern</translation>
    </message>
    <message>
        <source>Change light radius</source>
        <translation>Lichtradius ändern</translation>
    </message>
    <message>
        <source>Change spot cone</source>
        <translation>Spotkegel ändern</translation>
    </message>
    <message>
        <source>Change sun size</source>
        <translation>Sonnengröße ändern</translation>
    </message>
    <message>
        <source>Change projection</source>
        <translation>Projektion ändern</translation>
    </message>
    <message>
        <source>Change field of view</source>
        <translation>Sichtfeld ändern</translation>
    </message>
    <message>
        <source>Change aperture</source>
        <translation>Blende ändern</translation>
    </message>
    <message>
        <source>Change focus distance</source>
        <translation>Fokusdistanz ändern</translation>
    </message>
    <message>
        <source>Change clipping</source>
        <translation>Clipping ändern</translation>
    </message>
    <message>
        <source>Change aspect ratio</source>
        <translation>Seitenverhältnis ändern</translation>
    </message>
    <message>
        <source>Change shape</source>
        <translation>Form ändern</translation>
    </message>
    <message>
        <source>Change radius</source>
        <translation>Radius ändern</translation>
    </message>
    <message>
        <source>Change height</source>
        <translation>Höhe ändern</translation>
    </message>
    <message>
        <source>Change size</source>
        <translation>Größe ändern</translation>
    </message>
    <message>
        <source>Change material</source>
        <translation>Material ändern</translation>
    </message>
    <message>
        <source>Change base colour</source>
        <translation>Grundfarbe ändern</translation>
    </message>
    <message>
        <source>Change opacity</source>
        <translation>Deckkraft ändern</translation>
    </message>
    <message>
        <source>Change metallic</source>
        <translation>Metallisch ändern</translation>
    </message>
    <message>
        <source>Change roughness</source>
        <translation>Rauheit ändern</translation>
    </message>
    <message>
        <source>Change emission</source>
        <translation>Emission ändern</translation>
    </message>
    <message>
        <source>Change emission strength</source>
        <translation>Emissionsstärke ändern</translation>
    </message>
    <message>
        <source>Change specular</source>
        <translation>Spiegelung ändern</translation>
    </message>
    <message>
        <source>Change transmission</source>
        <translation>Transmission ändern</translation>
    </message>
    <message>
        <source>Change index of refraction</source>
        <translation>Brechungsindex ändern</translation>
    </message>
    <message>
        <source>Change volume</source>
        <translation>Volumen ändern</translation>
    </message>
    <message>
        <source>Change alpha mode</source>
        <translation>Alphamodus ändern</translation>
    </message>
    <message>
        <source>Change double sided</source>
        <translation>Doppelseitig ändern</translation>
    </message>
    <message>
        <source>Change texture</source>
        <translation>Textur ändern</translation>
    </message>
    <message>
        <source>Rename material</source>
        <translation>Material umbenennen</translation>
    </message>
    <message>
        <source>Change bloom</source>
        <translation>Bloom ändern</translation>
    </message>
    <message>
        <source>New material</source>
        <translation>Neues Material</translation>
    </message>
    <message>
        <source>Duplicate material</source>
        <translation>Material duplizieren</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Material zuweisen</translation>
    </message>
    <message>
        <source>Change motion blur</source>
        <translation>Bewegungsunschärfe ändern</translation>
    </message>
    <message>
        <source>Change adaptive sampling</source>
        <translation>Adaptives Sampling ändern</translation>
    </message>
    <message>
        <source>Change fog</source>
        <translation>Nebel ändern</translation>
    </message>
    <message>
        <source>Add studio environment</source>
        <translation>Studio-Umgebung hinzufügen</translation>
    </message>
    <message>
        <source>Change sample blocks</source>
        <translation>Sample-Blöcke ändern</translation>
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
        <translation>Die Szene hat noch keinen Dateinamen: Speichern unter verwenden.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
</context>
<context>
    <name>glint::editor::EditOperations</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>Nichts ist ausgewählt.</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>The node no longer exists.</source>
        <translation>Der Knoten existiert nicht mehr.</translation>
    </message>
    <message>
        <source>A node cannot be moved into itself or its own children.</source>
        <translation>Ein Knoten kann nicht in sich selbst oder seine Kinder verschoben werden.</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Neu zuordnen</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>glint::editor::ExportDialog</name>
    <message>
        <source>Export image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>Export animation</source>
        <translation>Animation exportieren</translation>
    </message>
    <message>
        <source>Output file</source>
        <translation>Ausgabedatei</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <source>Images (*.exr *.png *.jpg *.tif)</source>
        <translation>Bilder (*.exr *.png *.jpg *.tif)</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgabe</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Konfiguration</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Samples pro Pixel</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <source>EXR layers</source>
        <translation>EXR-Ebenen</translation>
    </message>
    <message>
        <source>all, none, or a list of albedo, normal, depth, id, variance</source>
        <translation>all, none oder eine Liste aus albedo, normal, depth, id, variance</translation>
    </message>
    <message>
        <source>Render passes</source>
        <translation>Render-Passes</translation>
    </message>
    <message>
        <source>EXR only, Accumulate and Reference: none, all, light, or a list of DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</source>
        <translation>Nur EXR, Accumulate und Reference: none, all, light oder eine Liste aus DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <source>First frame</source>
        <translation>Erstes Bild</translation>
    </message>
    <message>
        <source>Last frame</source>
        <translation>Letztes Bild</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>Video file</source>
        <translation>Videodatei</translation>
    </message>
    <message>
        <source>optional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</source>
        <translation>optional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Video</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Rendering...</source>
        <translation>Rendern...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryModel</name>
    <message>
        <source>&lt;empty&gt;</source>
        <translation>&lt;leer&gt;</translation>
    </message>
    <message>
        <source> (saved)</source>
        <translation> (gespeichert)</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryPanel</name>
    <message>
        <source>Undo history</source>
        <translation>Rückgängig-Verlauf</translation>
    </message>
</context>
<context>
    <name>glint::editor::KeyedTransform</name>
    <message>
        <source>Transform and key</source>
        <translation>Transformieren und keyen</translation>
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
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop reading the file; the open scene stays as it is</source>
        <translation>Beendet das Lesen der Datei; die offene Szene bleibt, wie sie ist</translation>
    </message>
    <message>
        <source>Loading progress</source>
        <translation>Ladefortschritt</translation>
    </message>
</context>
<context>
    <name>glint::editor::LogPanel</name>
    <message>
        <source>Log messages</source>
        <translation>Protokollmeldungen</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Clear the log</source>
        <translation>Protokoll leeren</translation>
    </message>
    <message>
        <source>info</source>
        <translation>Info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
</context>
<context>
    <name>glint::editor::MainWindow</name>
    <message>
        <source>Glint scene editor</source>
        <translation>Glint-Szeneneditor</translation>
    </message>
    <message>
        <source>Scene to open</source>
        <translation>Zu öffnende Szene</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>The viewport is not available in this build.</source>
        <translation>Die Ansicht ist in diesem Build nicht verfügbar.</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Gliederung</translation>
    </message>
    <message>
        <source>Undo history</source>
        <translation>Rückgängig-Verlauf</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Nothing selected</source>
        <translation>Nichts ausgewählt</translation>
    </message>
    <message>
        <source>Selected: %1</source>
        <translation>Ausgewählt: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes selected</source>
        <translation><numerusform>%n Knoten ausgewählt</numerusform><numerusform>%n Knoten ausgewählt</numerusform></translation>
    </message>
    <message>
        <source>Selection</source>
        <translation>Auswahl</translation>
    </message>
    <message>
        <source>Scene statistics</source>
        <translation>Szenenstatistik</translation>
    </message>
    <message>
        <source>Render progress</source>
        <translation>Renderfortschritt</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>"%1" has unsaved changes. Save them first?</source>
        <translation>"%1" hat ungespeicherte Änderungen. Zuerst speichern?</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Cannot import %1: %2</source>
        <translation>%1 kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>%1 importiert</translation>
    </message>
    <message>
        <source>Cannot save: %1</source>
        <translation>Speichern nicht möglich: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Szene speichern</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb)</source>
        <translation>glTF-Szenen (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>an untitled scene</source>
        <translation>eine unbenannte Szene</translation>
    </message>
    <message>
        <source>Cannot recover the autosaved copy: %1</source>
        <translation>Die automatisch gespeicherte Kopie kann nicht wiederhergestellt werden: %1</translation>
    </message>
    <message>
        <source>Recovered the autosaved copy of %1</source>
        <translation>Automatisch gespeicherte Kopie von %1 wiederhergestellt</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Scenes (*.gltf *.glb *.glint.json);;All files (*)</source>
        <translation>Szenen (*.gltf *.glb *.glint.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importieren...</translation>
    </message>
    <message>
        <source>Import into the scene</source>
        <translation>In die Szene importieren</translation>
    </message>
    <message>
        <source>Scenes and models (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;All files (*)</source>
        <translation>Szenen und Modelle (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Einstellungen...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>D&amp;uplizieren</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>&amp;Alles auswählen</translation>
    </message>
    <message>
        <source>Select &amp;None</source>
        <translation>Auswahl au&amp;fheben</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Bereiche</translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation>&amp;Design</translation>
    </message>
    <message>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Dunkel</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Glint</source>
        <translation>Ü&amp;ber Glint</translation>
    </message>
    <message>
        <source>About Glint</source>
        <translation>Über Glint</translation>
    </message>
    <message>
        <source>Glint %1: a scene editor with a built-in OpenGL 4.1 path tracer.</source>
        <translation>Glint %1: ein Szeneneditor mit eingebautem OpenGL-4.1-Pathtracer.</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>View toolbar</source>
        <translation>Ansichtswerkzeugleiste</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>%1 &amp;rückgängig machen</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>%1 &amp;wiederholen</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>Export &amp;Image...</source>
        <translation>&amp;Bild exportieren...</translation>
    </message>
    <message>
        <source>Export A&amp;nimation...</source>
        <translation>A&amp;nimation exportieren...</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Öffne %1</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importiere %1</translation>
    </message>
    <message>
        <source>Recovering an untitled scene</source>
        <translation>Stelle eine unbenannte Szene wieder her</translation>
    </message>
    <message>
        <source>Recovering %1</source>
        <translation>Stelle %1 wieder her</translation>
    </message>
    <message>
        <source>Cannot open %1:
%2</source>
        <translation>%1 kann nicht geöffnet werden:
%2</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Import von %1 abgebrochen</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>Öffnen von %1 abgebrochen</translation>
    </message>
    <message>
        <source>This display gives no OpenGL 4.1 core context, so the editor opens without its viewport; `glint render` renders headless (EGL).</source>
        <translation>Diese Anzeige bietet keinen OpenGL-4.1-Core-Kontext, daher öffnet sich der Editor ohne Ansicht; `glint render` rendert ohne Anzeige (EGL).</translation>
    </message>
    <message>
        <source>%1, %2, configuration: %3</source>
        <translation>%1, %2, Konfiguration: %3</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes</source>
        <translation><numerusform>%n Knoten</numerusform><numerusform>%n Knoten</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n triangles</source>
        <translation><numerusform>%n Dreieck</numerusform><numerusform>%n Dreiecke</numerusform></translation>
    </message>
    <message>
        <source>%1 (autosaved %2)</source>
        <translation>%1 (automatisch gespeichert %2)</translation>
    </message>
    <message>
        <source>Discard all autosaved copies</source>
        <translation>Alle automatisch gespeicherten Kopien verwerfen</translation>
    </message>
    <message>
        <source>Nothing to recover</source>
        <translation>Nichts wiederherzustellen</translation>
    </message>
    <message>
        <source>Glint did not close normally: the copy of %1 autosaved at %2 is newer than the file.</source>
        <translation>Glint wurde nicht normal beendet: die um %2 automatisch gespeicherte Kopie von %1 ist neuer als die Datei.</translation>
    </message>
    <message>
        <source>Glint did not close normally: unsaved work on %1 was autosaved at %2.</source>
        <translation>Glint wurde nicht normal beendet: ungespeicherte Arbeit an %1 wurde um %2 automatisch gespeichert.</translation>
    </message>
    <message numerus="yes">
        <source>%n more in File &gt; Recover.</source>
        <translation><numerusform>%n weitere unter Datei &gt; Wiederherstellen.</numerusform><numerusform>%n weitere unter Datei &gt; Wiederherstellen.</numerusform></translation>
    </message>
    <message>
        <source>Re&amp;cover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>There are no meshes in %1: nothing to import.</source>
        <translation>%1 enthält keine Meshes: nichts zu importieren.</translation>
    </message>
    <message>
        <source>%1 holds a mesh without any faces, so it cannot be imported.</source>
        <translation>%1 enthält ein Mesh ohne Flächen und kann daher nicht importiert werden.</translation>
    </message>
    <message>
        <source>%1 is in no format Glint imports (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</source>
        <translation>%1 hat kein Format, das Glint importiert (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</translation>
    </message>
    <message>
        <source>%1 ends too early: the file is damaged or was not copied completely.</source>
        <translation>%1 endet zu früh: die Datei ist beschädigt oder wurde nicht vollständig kopiert.</translation>
    </message>
    <message>
        <source>%1 cannot be read.</source>
        <translation>%1 kann nicht gelesen werden.</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 ist leer.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>Cannot import %1:
%2</source>
        <translation>%1 kann nicht importiert werden:
%2</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Neue Szene</translation>
    </message>
    <message>
        <source>New from &amp;template</source>
        <translation>Neu aus &amp;Vorlage</translation>
    </message>
    <message>
        <source>%1 (autosaved %2, older than the file)</source>
        <translation>%1 (automatisch gespeichert %2, älter als die Datei)</translation>
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
        <translation><numerusform>%n Nutzer</numerusform><numerusform>%n Nutzer</numerusform></translation>
    </message>
    <message>
        <source>%1: no node uses it (Delete unused removes it)</source>
        <translation>%1: kein Knoten verwendet es (Unbenutzte löschen entfernt es)</translation>
    </message>
    <message>
        <source>%1: drag it onto a node in the outliner or the viewport to assign it</source>
        <translation>%1: auf einen Knoten in der Gliederung oder der Ansicht ziehen, um es zuzuweisen</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialPresets</name>
    <message>
        <source>Plastic</source>
        <translation>Kunststoff</translation>
    </message>
    <message>
        <source>Rough</source>
        <translation>Rau</translation>
    </message>
    <message>
        <source>Glossy (clear coat)</source>
        <translation>Glänzend (Klarlack)</translation>
    </message>
    <message>
        <source>Metal</source>
        <translation>Metall</translation>
    </message>
    <message>
        <source>Gold</source>
        <translation>Gold</translation>
    </message>
    <message>
        <source>Brushed metal</source>
        <translation>Gebürstetes Metall</translation>
    </message>
    <message>
        <source>Glass</source>
        <translation>Glas</translation>
    </message>
    <message>
        <source>Frosted glass</source>
        <translation>Milchglas</translation>
    </message>
    <message>
        <source>Emitter</source>
        <translation>Strahler</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialsPanel</name>
    <message>
        <source>Search materials</source>
        <translation>Materialien suchen</translation>
    </message>
    <message>
        <source>Material search</source>
        <translation>Materialsuche</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>A new material from a preset</source>
        <translation>Ein neues Material aus einer Vorlage</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>A copy of the selected material</source>
        <translation>Eine Kopie des ausgewählten Materials</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Rename the selected material</source>
        <translation>Das ausgewählte Material umbenennen</translation>
    </message>
    <message>
        <source>Delete unused</source>
        <translation>Unbenutzte löschen</translation>
    </message>
    <message>
        <source>Remove every material no node uses</source>
        <translation>Entfernt jedes Material, das kein Knoten verwendet</translation>
    </message>
    <message>
        <source>Assign to selection</source>
        <translation>Der Auswahl zuweisen</translation>
    </message>
    <message>
        <source>Give the selected material to every selected shape and mesh (one undo step)</source>
        <translation>Gibt das ausgewählte Material jeder ausgewählten Form und jedem Netz (ein Rückgängig-Schritt)</translation>
    </message>
    <message numerus="yes">
        <source>%n unused materials removed.</source>
        <translation><numerusform>%n unbenutztes Material entfernt.</numerusform><numerusform>%n unbenutzte Materialien entfernt.</numerusform></translation>
    </message>
    <message>
        <source>Select a material in the list first.</source>
        <translation>Zuerst ein Material in der Liste auswählen.</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeKeyTracks</name>
    <message>
        <source>Node keys</source>
        <translation>Knotenschlüssel</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeNames</name>
    <message>
        <source>Sphere %1</source>
        <translation>Kugel %1</translation>
    </message>
    <message>
        <source>Quad %1</source>
        <translation>Viereck %1</translation>
    </message>
    <message>
        <source>Disk %1</source>
        <translation>Scheibe %1</translation>
    </message>
    <message>
        <source>Box %1</source>
        <translation>Quader %1</translation>
    </message>
    <message>
        <source>Cylinder %1</source>
        <translation>Zylinder %1</translation>
    </message>
    <message>
        <source>Ground plane %1</source>
        <translation>Bodenebene %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>Sun %1</source>
        <translation>Sonne %1</translation>
    </message>
    <message>
        <source>Point light %1</source>
        <translation>Punktlicht %1</translation>
    </message>
    <message>
        <source>Spot light %1</source>
        <translation>Spotlicht %1</translation>
    </message>
    <message>
        <source>Mesh %1</source>
        <translation>Mesh %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Kamera %1</translation>
    </message>
    <message>
        <source>Area light %1</source>
        <translation>Flächenlicht %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerModel</name>
    <message>
        <source>Mesh</source>
        <translation>Netz</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
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
        <translation>Sichtbar</translation>
    </message>
    <message>
        <source>Hidden</source>
        <translation>Ausgeblendet</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>%1 (%2; the file gives it no name)</source>
        <translation>%1 (%2; die Datei gibt ihm keinen Namen)</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerPanel</name>
    <message>
        <source>Filter by name</source>
        <translation>Nach Name filtern</translation>
    </message>
    <message>
        <source>Outliner filter</source>
        <translation>Gliederungsfilter</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add a shape, light or camera</source>
        <translation>Form, Licht oder Kamera hinzufügen</translation>
    </message>
    <message>
        <source>Scene outliner</source>
        <translation>Szenengliederung</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Quader</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Viereck</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Scheibe</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Bodenebene</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Point light</source>
        <translation>Punktlicht</translation>
    </message>
    <message>
        <source>Spot light</source>
        <translation>Spotlicht</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Sonne</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Empty group</source>
        <translation>Leere Gruppe</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Area rectangle</source>
        <translation>Flächenrechteck</translation>
    </message>
    <message>
        <source>Area disk</source>
        <translation>Flächenscheibe</translation>
    </message>
    <message>
        <source>Area sphere</source>
        <translation>Flächenkugel</translation>
    </message>
    <message>
        <source>Portal pair</source>
        <translation>Portalpaar</translation>
    </message>
    <message>
        <source>Studio environment</source>
        <translation>Studio-Umgebung</translation>
    </message>
</context>
<context>
    <name>glint::editor::PortalEdits</name>
    <message>
        <source>Add Portal Pair</source>
        <translation>Portalpaar hinzufügen</translation>
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
        <translation>Nur ein Viereck kann ein Portal sein.</translation>
    </message>
    <message>
        <source>A portal cannot lead to itself.</source>
        <translation>Ein Portal kann nicht zu sich selbst führen.</translation>
    </message>
    <message>
        <source>A portal can only lead to another quad.</source>
        <translation>Ein Portal kann nur zu einem anderen Viereck führen.</translation>
    </message>
    <message>
        <source>Link Portals</source>
        <translation>Portale verbinden</translation>
    </message>
    <message>
        <source>Unlink Portal</source>
        <translation>Portal trennen</translation>
    </message>
</context>
<context>
    <name>glint::editor::Preferences</name>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
</context>
<context>
    <name>glint::editor::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Allgemein</translation>
    </message>
    <message>
        <source>Keymap</source>
        <translation>Tastenbelegung</translation>
    </message>
    <message>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Dunkel</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Design</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Autosave interval</source>
        <translation>Intervall für automatisches Speichern</translation>
    </message>
    <message>
        <source>Autosave every</source>
        <translation>Automatisch speichern alle</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Shortcut for %1</source>
        <translation>Tastenkürzel für %1</translation>
    </message>
    <message>
        <source>Shortcut conflict</source>
        <translation>Tastenkürzel-Konflikt</translation>
    </message>
    <message>
        <source>%1 is used by both "%2" and "%3".</source>
        <translation>%1 wird von "%2" und "%3" verwendet.</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Keine Grenze</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Samples der Ansicht</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here (renders use the Scene panel's samples)</source>
        <translation>Die Ansicht hört hier auf, Samples pro Pixel hinzuzufügen (Renderings verwenden die Samples des Szene-Panels)</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Reset all to defaults</source>
        <translation>Alle auf Standard zurücksetzen</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertiesPanel</name>
    <message>
        <source>Scene settings</source>
        <translation>Szeneneinstellungen</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Select a node in the outliner or the viewport to edit it.</source>
        <translation>Einen Knoten in der Gliederung oder der Ansicht auswählen, um ihn zu bearbeiten.</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyEdits</name>
    <message>
        <source>Edit %1 nodes</source>
        <translation>%1 Knoten bearbeiten</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyForm</name>
    <message>
        <source>Texture %1</source>
        <translation>Textur %1</translation>
    </message>
    <message>
        <source>%1 thumbnail</source>
        <translation>Vorschaubild: %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Material: %1</source>
        <translation>Material: %1</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>Grundfarbe</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Deckkraft</translation>
    </message>
    <message>
        <source>Base colour texture</source>
        <translation>Grundfarbtextur</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Metallisch</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rauheit</translation>
    </message>
    <message>
        <source>Metallic-roughness texture</source>
        <translation>Metallisch-Rauheit-Textur</translation>
    </message>
    <message>
        <source>Normal texture</source>
        <translation>Normalentextur</translation>
    </message>
    <message>
        <source>Occlusion texture</source>
        <translation>Verdeckungstextur</translation>
    </message>
    <message>
        <source>Emission</source>
        <translation>Emission</translation>
    </message>
    <message>
        <source>Emission strength</source>
        <translation>Emissionsstärke</translation>
    </message>
    <message>
        <source>Emission texture</source>
        <translation>Emissionstextur</translation>
    </message>
    <message>
        <source>Specular</source>
        <translation>Spiegelnd</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>Spiegelfarbe</translation>
    </message>
    <message>
        <source>Specular texture</source>
        <translation>Spiegeltextur</translation>
    </message>
    <message>
        <source>Specular colour texture</source>
        <translation>Spiegelfarbtextur</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>Transmission</translation>
    </message>
    <message>
        <source>Transmission texture</source>
        <translation>Transmissionstextur</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>Brechungsindex</translation>
    </message>
    <message>
        <source>Thickness</source>
        <translation>Dicke</translation>
    </message>
    <message>
        <source>Thickness texture</source>
        <translation>Dickentextur</translation>
    </message>
    <message>
        <source>Attenuation distance (m)</source>
        <translation>Dämpfungsdistanz (m)</translation>
    </message>
    <message>
        <source>Attenuation colour</source>
        <translation>Dämpfungsfarbe</translation>
    </message>
    <message>
        <source>Alpha mode</source>
        <translation>Alphamodus</translation>
    </message>
    <message>
        <source>Opaque</source>
        <translation>Deckend</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <source>Blend</source>
        <translation>Überblenden</translation>
    </message>
    <message>
        <source>Alpha cutoff</source>
        <translation>Alpha-Schwelle</translation>
    </message>
    <message>
        <source>Double sided</source>
        <translation>Beidseitig</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Sichtbar</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformation</translation>
    </message>
    <message>
        <source>Position %1</source>
        <translation>Position %1</translation>
    </message>
    <message>
        <source>Rotation %1 (degrees)</source>
        <translation>Drehung %1 (Grad)</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <translation>Skalierung %1</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Viereck</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Scheibe</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Quader</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Bodenebene</translation>
    </message>
    <message>
        <source>Radius (m)</source>
        <translation>Radius (m)</translation>
    </message>
    <message>
        <source>Height (m)</source>
        <translation>Höhe (m)</translation>
    </message>
    <message>
        <source>Size %1 (m)</source>
        <translation>Größe %1 (m)</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Sonne</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <source>lux</source>
        <translation>lx</translation>
    </message>
    <message>
        <source>cd</source>
        <translation>cd</translation>
    </message>
    <message>
        <source>Blender units</source>
        <translation>Blender-Einheiten</translation>
    </message>
    <message>
        <source>raw units</source>
        <translation>Roheinheiten</translation>
    </message>
    <message>
        <source>Intensity (%1, %2)</source>
        <translation>Intensität (%1, %2)</translation>
    </message>
    <message>
        <source>Range (m, 0 = infinite)</source>
        <translation>Reichweite (m, 0 = unendlich)</translation>
    </message>
    <message>
        <source>Inner cone (degrees)</source>
        <translation>Innerer Kegel (Grad)</translation>
    </message>
    <message>
        <source>Outer cone (degrees)</source>
        <translation>Äußerer Kegel (Grad)</translation>
    </message>
    <message>
        <source>Sun angular diameter (degrees)</source>
        <translation>Winkeldurchmesser der Sonne (Grad)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Projection</source>
        <translation>Projektion</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspektivisch</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <translation>Orthografisch</translation>
    </message>
    <message>
        <source>Vertical field of view (degrees)</source>
        <translation>Vertikales Sichtfeld (Grad)</translation>
    </message>
    <message>
        <source>Lens radius (m)</source>
        <translation>Objektivradius (m)</translation>
    </message>
    <message>
        <source>Focus distance (m)</source>
        <translation>Fokusdistanz (m)</translation>
    </message>
    <message>
        <source>Exposure (EV)</source>
        <translation>Belichtung (LW)</translation>
    </message>
    <message>
        <source>Near clip (m)</source>
        <translation>Nahe Schnittebene (m)</translation>
    </message>
    <message>
        <source>Active camera</source>
        <translation>Aktive Kamera</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Umgebung</translation>
    </message>
    <message>
        <source>HDR file</source>
        <translation>HDR-Datei</translation>
    </message>
    <message>
        <source>Colour (no file)</source>
        <translation>Farbe (ohne Datei)</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensität</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>Drehung (Grad)</translation>
    </message>
    <message>
        <source>Render settings</source>
        <translation>Render-Einstellungen</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Konfiguration</translation>
    </message>
    <message>
        <source>Width (px)</source>
        <translation>Breite (px)</translation>
    </message>
    <message>
        <source>Height (px)</source>
        <translation>Höhe (px)</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Samples pro Pixel</translation>
    </message>
    <message>
        <source>Bounces</source>
        <translation>Reflexionen</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <source>Tonemapper</source>
        <translation>Tonemapper</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keiner</translation>
    </message>
    <message>
        <source>ACES (fitted)</source>
        <translation>ACES (angenähert)</translation>
    </message>
    <message>
        <source>Khronos PBR Neutral</source>
        <translation>Khronos PBR Neutral</translation>
    </message>
    <message>
        <source>Radiance clamp (0 = off)</source>
        <translation>Strahldichte-Begrenzung (0 = aus)</translation>
    </message>
    <message>
        <source>Light units</source>
        <translation>Lichteinheiten</translation>
    </message>
    <message>
        <source>Blender (W = lm / 683)</source>
        <translation>Blender (W = lm / 683)</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Roh</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <source>Choose an HDR environment file</source>
        <translation>HDR-Umgebungsdatei wählen</translation>
    </message>
    <message>
        <source>Environment map</source>
        <translation>Umgebungskarte</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>HDR-Bilder (*.hdr *.exr);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Camera and timeline</source>
        <translation>Kamera und Zeitleiste</translation>
    </message>
    <message>
        <source>(the first camera)</source>
        <translation>(die erste Kamera)</translation>
    </message>
    <message>
        <source>Timeline start (s)</source>
        <translation>Beginn der Zeitleiste (s)</translation>
    </message>
    <message>
        <source>Timeline end (s, 0 = the animation's)</source>
        <translation>Ende der Zeitleiste (s, 0 = das der Animation)</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Bilder pro Sekunde</translation>
    </message>
    <message>
        <source>Frames per second must be a positive number or a ratio such as 24000/1001, not "%1".</source>
        <translation>Bilder pro Sekunde müssen eine positive Zahl oder ein Verhältnis wie 24000/1001 sein, nicht "%1".</translation>
    </message>
    <message>
        <source>Real-time reconstruction</source>
        <translation>Echtzeit-Rekonstruktion</translation>
    </message>
    <message>
        <source>TAA blend (current frame)</source>
        <translation>TAA-Mischung (aktuelles Bild)</translation>
    </message>
    <message>
        <source>TAA clip box (std. deviations)</source>
        <translation>TAA-Clip-Box (Standardabweichungen)</translation>
    </message>
    <message>
        <source>TAA perceptual blend</source>
        <translation>Wahrnehmungsbasierte TAA-Mischung</translation>
    </message>
    <message>
        <source>SVGF a-trous iterations</source>
        <translation>SVGF-À-trous-Iterationen</translation>
    </message>
    <message>
        <source>SVGF temporal alpha</source>
        <translation>SVGF-Zeit-Alpha</translation>
    </message>
    <message>
        <source>SVGF moments alpha</source>
        <translation>SVGF-Momente-Alpha</translation>
    </message>
    <message>
        <source>SVGF luminance sigma</source>
        <translation>SVGF-Luminanz-Sigma</translation>
    </message>
    <message>
        <source>SVGF normal sigma (exponent)</source>
        <translation>SVGF-Normalen-Sigma (Exponent)</translation>
    </message>
    <message>
        <source>SVGF depth sigma</source>
        <translation>SVGF-Tiefen-Sigma</translation>
    </message>
    <message>
        <source>SVGF firefly ratio</source>
        <translation>SVGF-Glühwürmchen-Verhältnis</translation>
    </message>
    <message>
        <source>TAA history clipping</source>
        <translation>TAA-Verlaufsbeschneidung</translation>
    </message>
    <message>
        <source>Variance clip (YCoCg)</source>
        <translation>Varianz-Beschneidung (YCoCg)</translation>
    </message>
    <message>
        <source>Min/max clamp</source>
        <translation>Min/Max-Begrenzung</translation>
    </message>
    <message>
        <source>None (ghosts)</source>
        <translation>Keine (Geisterbilder)</translation>
    </message>
    <message>
        <source>"%1" is relative, but the scene has no folder yet: choose the file with Browse, or save the scene first.</source>
        <translation>"%1" ist relativ, aber die Szene hat noch keinen Ordner: Wählen Sie die Datei mit Durchsuchen oder speichern Sie zuerst die Szene.</translation>
    </message>
    <message>
        <source>Cannot read the environment image %1. Choose it again with Browse, or clear the field to use the colour below.</source>
        <translation>Das Umgebungsbild %1 kann nicht gelesen werden. Wählen Sie es mit Durchsuchen erneut aus oder leeren Sie das Feld, um die Farbe darunter zu verwenden.</translation>
    </message>
    <message>
        <source>Environment image status</source>
        <translation>Status des Umgebungsbilds</translation>
    </message>
    <message>
        <source>An infinite plane: the node's y = 0, facing +Y; move and turn it with the transform. It has no size. In the glTF file other programs (Blender) get a 200 m square in its place.</source>
        <translation>Eine unendliche Ebene: y = 0 des Knotens, nach +Y gerichtet; mit der Transformation verschieben und drehen. Sie hat keine Größe. In der glTF-Datei erhalten andere Programme (Blender) an ihrer Stelle ein Quadrat von 200 m.</translation>
    </message>
    <message>
        <source>Half height (m)</source>
        <translation>Halbe Höhe (m)</translation>
    </message>
    <message>
        <source>AgX</source>
        <translation>AgX</translation>
    </message>
    <message>
        <source>Reinhard (extended)</source>
        <translation>Reinhard (erweitert)</translation>
    </message>
    <message>
        <source>Hable (Uncharted 2)</source>
        <translation>Hable (Uncharted 2)</translation>
    </message>
    <message>
        <source>Bloom strength (0 = off)</source>
        <translation>Bloom-Stärke (0 = aus)</translation>
    </message>
    <message>
        <source>Bloom radius (of the height)</source>
        <translation>Bloom-Radius (relativ zur Höhe)</translation>
    </message>
    <message>
        <source>Edit sampler</source>
        <translation>Sampler bearbeiten</translation>
    </message>
    <message>
        <source>Load texture</source>
        <translation>Textur laden</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Laden…</translation>
    </message>
    <message>
        <source>Load an image file (PNG, JPEG, EXR, HDR, TIFF) into this slot</source>
        <translation>Eine Bilddatei (PNG, JPEG, EXR, HDR, TIFF) in diesen Platz laden</translation>
    </message>
    <message>
        <source>Load %1</source>
        <translation>%1 laden</translation>
    </message>
    <message>
        <source>UV set</source>
        <translation>UV-Satz</translation>
    </message>
    <message>
        <source>Repeat</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Clamp to edge</source>
        <translation>Am Rand festhalten</translation>
    </message>
    <message>
        <source>Mirrored repeat</source>
        <translation>Gespiegelt wiederholen</translation>
    </message>
    <message>
        <source>Wrap U</source>
        <translation>Umbruch U</translation>
    </message>
    <message>
        <source>Wrap V</source>
        <translation>Umbruch V</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Nearest</source>
        <translation>Nächster</translation>
    </message>
    <message>
        <source>Offset U</source>
        <translation>Versatz U</translation>
    </message>
    <message>
        <source>Offset V</source>
        <translation>Versatz V</translation>
    </message>
    <message>
        <source>Scale U</source>
        <translation>Skalierung U</translation>
    </message>
    <message>
        <source>Scale V</source>
        <translation>Skalierung V</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Show this primitive's material below</source>
        <translation>Das Material dieses Primitivs unten zeigen</translation>
    </message>
    <message numerus="yes">
        <source>Primitive %1 (%n triangles)</source>
        <translation><numerusform>Primitiv %1 (%n Dreieck)</numerusform><numerusform>Primitiv %1 (%n Dreiecke)</numerusform></translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>(default)</source>
        <translation>(Standard)</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>Motion blur shutter (frames, 0 = off)</source>
        <translation>Verschluss Bewegungsunschärfe (Bilder, 0 = aus)</translation>
    </message>
    <message>
        <source>Rectangle</source>
        <translation>Rechteck</translation>
    </message>
    <message>
        <source>Power (W)</source>
        <translation>Leistung (W)</translation>
    </message>
    <message>
        <source>Size X (m)</source>
        <translation>Größe X (m)</translation>
    </message>
    <message>
        <source>Size Y (m)</source>
        <translation>Größe Y (m)</translation>
    </message>
    <message>
        <source>Diameter (m)</source>
        <translation>Durchmesser (m)</translation>
    </message>
    <message>
        <source>Emits its power evenly from the front face (the light's -Z) of the rectangle or disk, or the outside of the sphere; in the glTF file other programs get an emissive mesh.</source>
        <translation>Strahlt seine Leistung gleichmäßig von der Vorderseite (dem -Z des Lichts) des Rechtecks oder der Scheibe oder von der Außenseite der Kugel ab; in der glTF-Datei erhalten andere Programme ein leuchtendes Mesh.</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Samples der Ansicht</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Keine Grenze</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here; renders use the samples per pixel above</source>
        <translation>Die Ansicht hört hier auf, Samples pro Pixel hinzuzufügen; Renderings verwenden die Samples pro Pixel oben</translation>
    </message>
    <message>
        <source>Rendering</source>
        <translation>Rendern</translation>
    </message>
    <message>
        <source>Noise threshold (adaptive sampling, 0 = off)</source>
        <translation>Rauschschwelle (adaptives Sampling, 0 = aus)</translation>
    </message>
    <message>
        <source>Adaptive minimum samples (0 = automatic)</source>
        <translation>Adaptive Mindest-Samples (0 = automatisch)</translation>
    </message>
    <message>
        <source>Scatter anisotropy</source>
        <translation>Streuanisotropie</translation>
    </message>
    <message>
        <source>Scatter colour</source>
        <translation>Streufarbe</translation>
    </message>
    <message>
        <source>Fog</source>
        <translation>Nebel</translation>
    </message>
    <message>
        <source>Density (1/m)</source>
        <translation>Dichte (1/m)</translation>
    </message>
    <message>
        <source>Anisotropy</source>
        <translation>Anisotropie</translation>
    </message>
    <message>
        <source>Height falloff (1/m)</source>
        <translation>Höhenabfall (1/m)</translation>
    </message>
    <message>
        <source>Base height (m)</source>
        <translation>Basishöhe (m)</translation>
    </message>
    <message>
        <source>node %1, deleted</source>
        <translation>Knoten %1, gelöscht</translation>
    </message>
    <message>
        <source>Not paired: the other side does not lead back here, so this quad is an ordinary surface. Choose a quad to pair them again.</source>
        <translation>Nicht gepaart: Die andere Seite führt nicht hierher zurück, daher ist dieses Viereck eine gewöhnliche Fläche. Wähle ein Viereck, um sie wieder zu paaren.</translation>
    </message>
    <message>
        <source>What enters this quad leaves the quad chosen here, and the other way round.</source>
        <translation>Was in dieses Viereck eintritt, verlässt das hier gewählte Viereck, und umgekehrt.</translation>
    </message>
    <message>
        <source>Portal to</source>
        <translation>Portal zu</translation>
    </message>
    <message>
        <source>Adaptive goal</source>
        <translation>Adaptives Ziel</translation>
    </message>
    <message>
        <source>Even noise (as Cycles)</source>
        <translation>Gleichmäßiges Rauschen (wie Cycles)</translation>
    </message>
    <message>
        <source>Least mean error</source>
        <translation>Geringster mittlerer Fehler</translation>
    </message>
    <message>
        <source>Sample blocks (pixels sharing a sequence)</source>
        <translation>Sample-Blöcke (Pixel mit gemeinsamer Folge)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
</context>
<context>
    <name>glint::editor::RecoveryBar</name>
    <message>
        <source>Recover unsaved work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Delete the autosaved copy</source>
        <translation>Die automatisch gespeicherte Kopie löschen</translation>
    </message>
    <message>
        <source>Later (File &gt; Recover keeps it)</source>
        <translation>Später (bleibt unter Datei &gt; Wiederherstellen)</translation>
    </message>
    <message>
        <source>Hide</source>
        <translation>Ausblenden</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderHost</name>
    <message>
        <source>Preparing the scene</source>
        <translation>Szene wird vorbereitet</translation>
    </message>
    <message>
        <source>building mesh BVHs</source>
        <translation>erstelle Mesh-BVHs</translation>
    </message>
    <message>
        <source>decoding textures</source>
        <translation>dekodiere Texturen</translation>
    </message>
    <message>
        <source>loading the environment</source>
        <translation>lade die Umgebung</translation>
    </message>
    <message>
        <source>packing the scene</source>
        <translation>packe die Szene</translation>
    </message>
    <message>
        <source>building the click picker</source>
        <translation>erstelle die Klickauswahl</translation>
    </message>
    <message>
        <source>Preparing the scene: %1 %2/%3</source>
        <translation>Szene wird vorbereitet: %1 %2/%3</translation>
    </message>
    <message>
        <source>Preparing the scene: %1</source>
        <translation>Szene wird vorbereitet: %1</translation>
    </message>
    <message>
        <source>Nothing in the scene emits light, so the path-traced image is black: add a light (Add &gt; Light &gt; Studio environment lights any model) or an emissive material, or give the environment a colour or an image (Scene tab).</source>
        <translation>Nichts in der Szene strahlt Licht aus, daher ist das Pathtracing-Bild schwarz: Fügen Sie ein Licht hinzu (Hinzufügen &gt; Licht &gt; Studio-Umgebung beleuchtet jedes Modell) oder ein emittierendes Material, oder geben Sie der Umgebung eine Farbe oder ein Bild (Reiter Szene).</translation>
    </message>
    <message>
        <source>Only emissive textures give light in this scene, so most of the path-traced image is dark: add a light (Add &gt; Light &gt; Studio environment lights any model), or give the environment a colour or an image (Scene tab).</source>
        <translation>In dieser Szene geben nur emittierende Texturen Licht, daher ist das Pathtracing-Bild größtenteils dunkel: Fügen Sie ein Licht hinzu (Hinzufügen &gt; Licht &gt; Studio-Umgebung beleuchtet jedes Modell) oder geben Sie der Umgebung eine Farbe oder ein Bild (Reiter Szene).</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderView</name>
    <message>
        <source>Viewport</source>
        <translation>Ansicht</translation>
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
        <translation>Pixel %1, %2
R %3  G %4  B %5 (linear)</translation>
    </message>
</context>
<context>
    <name>glint::editor::SceneLoader</name>
    <message>
        <source>reading the glTF file</source>
        <translation>lese die glTF-Datei</translation>
    </message>
    <message>
        <source>running the importer</source>
        <translation>führe den Importer aus</translation>
    </message>
</context>
<context>
    <name>glint::editor::SceneTemplates</name>
    <message>
        <source>Studio</source>
        <translation>Studio</translation>
    </message>
    <message>
        <source>Empty</source>
        <translation>Leer</translation>
    </message>
    <message>
        <source>Sun and sky</source>
        <translation>Sonne und Himmel</translation>
    </message>
    <message>
        <source>Cornell box</source>
        <translation>Cornell-Box</translation>
    </message>
    <message>
        <source>Cornell box in fog</source>
        <translation>Cornell-Box im Nebel</translation>
    </message>
    <message>
        <source>Portals</source>
        <translation>Portale</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimeRuler</name>
    <message>
        <source>Time ruler</source>
        <translation>Zeitlineal</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimelinePanel</name>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>Path camera</source>
        <translation>Pfadkamera</translation>
    </message>
    <message>
        <source>  %1 s  (frame %2)</source>
        <translation>  %1 s  (Bild %2)</translation>
    </message>
    <message>
        <source>Add key</source>
        <translation>Schlüssel hinzufügen</translation>
    </message>
    <message>
        <source>Add a camera-path key from the current view at the current time</source>
        <translation>Fügt aus der aktuellen Ansicht einen Kamerapfad-Schlüssel zur aktuellen Zeit hinzu</translation>
    </message>
    <message>
        <source>Delete key</source>
        <translation>Schlüssel löschen</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <source>Constant speed</source>
        <translation>Konstante Geschwindigkeit</translation>
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
        <translation>Sichtfeld</translation>
    </message>
    <message>
        <source>Focus</source>
        <translation>Fokus</translation>
    </message>
    <message>
        <source>Lens</source>
        <translation>Objektiv</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Key %1</source>
        <translation>Schlüssel %1</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Transformation verschlüsseln</translation>
    </message>
    <message>
        <source>Key the selected nodes' position, rotation and scale at the current time (K)</source>
        <translation>Setzt einen Schlüssel für Position, Drehung und Skalierung der ausgewählten Knoten zur aktuellen Zeit (K)</translation>
    </message>
    <message>
        <source>Copy key</source>
        <translation>Schlüssel kopieren</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Schlüssel einfügen</translation>
    </message>
    <message>
        <source>Key the selected nodes at the current time with the copied key's transform</source>
        <translation>Setzt für die ausgewählten Knoten zur aktuellen Zeit einen Schlüssel mit der Transformation des kopierten Schlüssels</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Stufen</translation>
    </message>
    <message>
        <source>Cubic</source>
        <translation>Kubisch</translation>
    </message>
    <message>
        <source>Auto key</source>
        <translation>Automatisch keyen</translation>
    </message>
    <message>
        <source>Key every moved, turned or scaled node at the current time (nodes with keys are always keyed)</source>
        <translation>Jeden verschobenen, gedrehten oder skalierten Knoten zur aktuellen Zeit keyen (Knoten mit Keys werden immer gekeyt)</translation>
    </message>
</context>
<context>
    <name>glint::editor::Viewport</name>
    <message>
        <source>Path traced</source>
        <translation>Pathtracing</translation>
    </message>
    <message>
        <source>Solid</source>
        <translation>Solid</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>Drahtgitter</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <source>Ambient occlusion</source>
        <translation>Umgebungsverdeckung</translation>
    </message>
    <message>
        <source>Motion vectors</source>
        <translation>Bewegungsvektoren</translation>
    </message>
    <message>
        <source>Variance</source>
        <translation>Varianz</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <source>BVH instance boxes</source>
        <translation>BVH-Instanzboxen</translation>
    </message>
    <message>
        <source>BVH traversal cost (heat map)</source>
        <translation>BVH-Traversierungskosten (Heatmap)</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Skalieren</translation>
    </message>
    <message>
        <source>Frame selection</source>
        <translation>Auswahl einpassen</translation>
    </message>
    <message>
        <source>Make scene camera from view</source>
        <translation>Szenenkamera aus Ansicht erstellen</translation>
    </message>
    <message>
        <source>Look through selected camera</source>
        <translation>Durch ausgewählte Kamera sehen</translation>
    </message>
    <message>
        <source>Snap (Ctrl inverts while dragging)</source>
        <translation>Einrasten (Strg kehrt beim Ziehen um)</translation>
    </message>
    <message>
        <source>Pixel inspector</source>
        <translation>Pixel-Inspektor</translation>
    </message>
    <message>
        <source>Take snapshot A</source>
        <translation>Schnappschuss A aufnehmen</translation>
    </message>
    <message>
        <source>Set render region</source>
        <translation>Renderbereich festlegen</translation>
    </message>
    <message>
        <source>Drag a rectangle: the path tracer renders only inside it</source>
        <translation>Ziehen Sie ein Rechteck auf: der Pathtracer rendert nur darin</translation>
    </message>
    <message>
        <source>Clear render region</source>
        <translation>Renderbereich löschen</translation>
    </message>
    <message>
        <source>Compare A | B</source>
        <translation>A | B vergleichen</translation>
    </message>
    <message>
        <source>Pick focus distance</source>
        <translation>Fokusabstand wählen</translation>
    </message>
    <message>
        <source>Click a surface: the camera looked through focuses at its depth</source>
        <translation>Klicken Sie auf eine Fläche: die Kamera, durch die Sie schauen, fokussiert auf ihre Tiefe</translation>
    </message>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>Fokuswahl wirkt durch eine Szenenkamera: wählen Sie zuerst eine aus und schauen Sie hindurch (0).</translation>
    </message>
    <message>
        <source>Click the surface to focus on (Esc cancels).</source>
        <translation>Klicken Sie auf die Fläche, die scharf sein soll (Esc bricht ab).</translation>
    </message>
    <message>
        <source>Pause viewport rendering</source>
        <translation>Rendern der Ansicht anhalten</translation>
    </message>
    <message>
        <source>Stop adding samples; edits are still shown at full resolution</source>
        <translation>Keine Samples mehr hinzufügen; Änderungen werden weiterhin in voller Auflösung gezeigt</translation>
    </message>
    <message>
        <source>Denoise still image</source>
        <translation>Standbild entrauschen</translation>
    </message>
    <message>
        <source>Filter the accumulated image while it converges (off: the raw running mean; renders are never filtered)</source>
        <translation>Das akkumulierte Bild filtern, während es konvergiert (aus: der rohe laufende Mittelwert; Renderings werden nie gefiltert)</translation>
    </message>
    <message>
        <source>coarse (1/%1 resolution)</source>
        <translation>grob (1/%1 Auflösung)</translation>
    </message>
    <message>
        <source>refining to full resolution: %1%</source>
        <translation>Verfeinerung auf volle Auflösung: %1%</translation>
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
        <translation>%1 spp, konvergiert (Sample-Grenze der Ansicht)</translation>
    </message>
    <message>
        <source>%1 spp, paused</source>
        <translation>%1 spp, angehalten</translation>
    </message>
    <message>
        <source>%1  |  %2 ms/frame</source>
        <translation>%1  |  %2 ms/Bild</translation>
    </message>
    <message>
        <source>Local axes</source>
        <translation>Lokale Achsen</translation>
    </message>
    <message>
        <source>Move and rotate along the selected node's own axes (off: the world's)</source>
        <translation>Entlang der eigenen Achsen des ausgewählten Knotens verschieben und drehen (aus: der Welt)</translation>
    </message>
    <message>
        <source>up to %1 spp, converged (noise threshold)</source>
        <translation>bis %1 spp, konvergiert (Rauschschwelle)</translation>
    </message>
    <message>
        <source>%1, %2% converged</source>
        <translation>%1, %2% konvergiert</translation>
    </message>
</context>
</TS>