<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="it" sourcelanguage="en">
<context>
    <name>FocusPick</name>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>La scelta del fuoco funziona attraverso una camera della scena: selezionane una e guarda attraverso (0).</translation>
    </message>
    <message>
        <source>Pick focus: %1 follows its camera path, whose keys set the focus; edit them in the timeline.</source>
        <translation>Scelta del fuoco: %1 segue il suo percorso, le cui chiavi fissano il fuoco; modificale nella timeline.</translation>
    </message>
    <message>
        <source>Pick focus: nothing under the cursor, the focus distance is unchanged.</source>
        <translation>Scelta del fuoco: niente sotto il cursore, la distanza di messa a fuoco non cambia.</translation>
    </message>
    <message>
        <source>Pick focus: the surface is behind the camera, the focus distance is unchanged.</source>
        <translation>Scelta del fuoco: la superficie è dietro la camera, la distanza di messa a fuoco non cambia.</translation>
    </message>
    <message>
        <source>Focus distance of %1: %2 m (%3)</source>
        <translation>Distanza di messa a fuoco di %1: %2 m (%3)</translation>
    </message>
</context>
<context>
    <name>OverlayPainter</name>
    <message>
        <source>BVH nodes + primitives</source>
        <translation>Nodi BVH + primitive</translation>
    </message>
</context>
<context>
    <name>glint::editor</name>
    <message>
        <source>%1 cannot be read as an image: %2</source>
        <translation>%1 non può essere letto come immagine: %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted: %2</source>
        <translation>%1 non può essere convertito: %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted to PNG: %2</source>
        <translation>%1 non può essere convertito in PNG: %2</translation>
    </message>
    <message>
        <source>The material no longer exists.</source>
        <translation>Il materiale non esiste più.</translation>
    </message>
    <message>
        <source>A material needs a name.</source>
        <translation>Un materiale ha bisogno di un nome.</translation>
    </message>
    <message>
        <source>Delete unused materials</source>
        <translation>Elimina materiali inutilizzati</translation>
    </message>
    <message>
        <source>Select a shape or a mesh to assign the material to.</source>
        <translation>Seleziona una forma o una mesh a cui assegnare il materiale.</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Assegna materiale</translation>
    </message>
    <message>
        <source>The mesh no longer exists.</source>
        <translation>La mesh non esiste più.</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 non esiste.</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 non può essere letto: %2</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 è vuoto.</translation>
    </message>
    <message>
        <source>Load texture %1</source>
        <translation>Carica texture %1</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Chiave trasformazione</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Incolla chiave</translation>
    </message>
</context>
<context>
    <name>glint::editor::Autosave</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>Impossibile creare la cartella di salvataggio automatico %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::ColorField</name>
    <message>
        <source>Choose a colour</source>
        <translation>Scegli un colore</translation>
    </message>
    <message>
        <source>%1 (sRGB); stored linear: %2, %3, %4</source>
        <translation>%1 (sRGB); valore lineare salvato: %2, %3, %4</translation>
    </message>
</context>
<context>
    <name>glint::editor::CommandLabels</name>
    <message>
        <source>Rename</source>
        <translation>Rinomina</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Sposta</translation>
    </message>
    <message>
        <source>Show/hide</source>
        <translation>Mostra/nascondi</translation>
    </message>
    <message>
        <source>Edit component</source>
        <translation>Modifica componente</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Cambia genitore</translation>
    </message>
    <message>
        <source>Edit settings</source>
        <translation>Modifica impostazioni</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Elimina</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplica</translation>
    </message>
    <message>
        <source>Add camera key</source>
        <translation>Aggiungi chiave camera</translation>
    </message>
    <message>
        <source>Edit camera key</source>
        <translation>Modifica chiave camera</translation>
    </message>
    <message>
        <source>Move camera key</source>
        <translation>Sposta chiave camera</translation>
    </message>
    <message>
        <source>Remove camera key</source>
        <translation>Rimuovi chiave camera</translation>
    </message>
    <message>
        <source>Camera path mode</source>
        <translation>Modalità del percorso camera</translation>
    </message>
    <message>
        <source>mesh</source>
        <translation>mesh</translation>
    </message>
    <message>
        <source>material</source>
        <translation>materiale</translation>
    </message>
    <message>
        <source>texture</source>
        <translation>texture</translation>
    </message>
    <message>
        <source>image</source>
        <translation>immagine</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>campionatore</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Aggiungi %1</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>Rimuovi %1</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>Duplica %1</translation>
    </message>
    <message>
        <source>Edit %1</source>
        <translation>Modifica %1</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importa %1</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Ruota</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Scala</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Trasformazione</translation>
    </message>
    <message>
        <source>Change configuration</source>
        <translation>Cambia configurazione</translation>
    </message>
    <message>
        <source>Change image size</source>
        <translation>Cambia dimensione immagine</translation>
    </message>
    <message>
        <source>Change samples per pixel</source>
        <translation>Cambia campioni per pixel</translation>
    </message>
    <message>
        <source>Change bounces</source>
        <translation>Cambia rimbalzi</translation>
    </message>
    <message>
        <source>Change seed</source>
        <translation>Cambia seme</translation>
    </message>
    <message>
        <source>Change exposure</source>
        <translation>Cambia esposizione</translation>
    </message>
    <message>
        <source>Change tonemapper</source>
        <translation>Cambia tone mapping</translation>
    </message>
    <message>
        <source>Change radiance clamp</source>
        <translation>Cambia limite di radianza</translation>
    </message>
    <message>
        <source>Change TAA settings</source>
        <translation>Cambia impostazioni TAA</translation>
    </message>
    <message>
        <source>Change SVGF settings</source>
        <translation>Cambia impostazioni SVGF</translation>
    </message>
    <message>
        <source>Change environment image</source>
        <translation>Cambia immagine d'ambiente</translation>
    </message>
    <message>
        <source>Change environment colour</source>
        <translation>Cambia colore d'ambiente</translation>
    </message>
    <message>
        <source>Change environment intensity</source>
        <translation>Cambia intensità d'ambiente</translation>
    </message>
    <message>
        <source>Rotate environment</source>
        <translation>Ruota ambiente</translation>
    </message>
    <message>
        <source>Change active camera</source>
        <translation>Cambia camera attiva</translation>
    </message>
    <message>
        <source>Change timeline range</source>
        <translation>Cambia intervallo della timeline</translation>
    </message>
    <message>
        <source>Change frame rate</source>
        <translation>Cambia frequenza fotogrammi</translation>
    </message>
    <message>
        <source>Change output</source>
        <translation>Cambia output</translation>
    </message>
    <message>
        <source>Change light units</source>
        <translation>Cambia unità della luce</translation>
    </message>
    <message>
        <source>Change light type</source>
        <translation>Cambia tipo di luce</translation>
    </message>
    <message>
        <source>Change light colour</source>
        <translation>Cambia colore della luce</translation>
    </message>
    <message>
        <source>Change light intensity</source>
        <translation>Cambia intensità della luce</translation>
    </message>
    <message>
        <source>Change light range</source>
        <translation>Cambia portata della luce</translation>
    </message>
    <message>
        <source>Change light radius</source>
        <translation>Cambia raggio della luce</translation>
    </message>
    <message>
        <source>Change spot cone</source>
        <translation>Cambia cono del faretto</translation>
    </message>
    <message>
        <source>Change sun size</source>
        <translation>Cambia dimensione del sole</translation>
    </message>
    <message>
        <source>Change projection</source>
        <translation>Cambia proiezione</translation>
    </message>
    <message>
        <source>Change field of view</source>
        <translation>Cambia campo visivo</translation>
    </message>
    <message>
        <source>Change aperture</source>
        <translation>Cambia apertura</translation>
    </message>
    <message>
        <source>Change focus distance</source>
        <translation>Cambia distanza di messa a fuoco</translation>
    </message>
    <message>
        <source>Change clipping</source>
        <translation>Cambia piani di ritaglio</translation>
    </message>
    <message>
        <source>Change aspect ratio</source>
        <translation>Cambia proporzioni</translation>
    </message>
    <message>
        <source>Change shape</source>
        <translation>Cambia forma</translation>
    </message>
    <message>
        <source>Change radius</source>
        <translation>Cambia raggio</translation>
    </message>
    <message>
        <source>Change height</source>
        <translation>Cambia altezza</translation>
    </message>
    <message>
        <source>Change size</source>
        <translation>Cambia dimensioni</translation>
    </message>
    <message>
        <source>Change material</source>
        <translation>Cambia materiale</translation>
    </message>
    <message>
        <source>Change base colour</source>
        <translation>Cambia colore base</translation>
    </message>
    <message>
        <source>Change opacity</source>
        <translation>Cambia opacità</translation>
    </message>
    <message>
        <source>Change metallic</source>
        <translation>Cambia metallicità</translation>
    </message>
    <message>
        <source>Change roughness</source>
        <translation>Cambia rugosità</translation>
    </message>
    <message>
        <source>Change emission</source>
        <translation>Cambia emissione</translation>
    </message>
    <message>
        <source>Change emission strength</source>
        <translation>Cambia intensità di emissione</translation>
    </message>
    <message>
        <source>Change specular</source>
        <translation>Cambia speculare</translation>
    </message>
    <message>
        <source>Change transmission</source>
        <translation>Cambia trasmissione</translation>
    </message>
    <message>
        <source>Change index of refraction</source>
        <translation>Cambia indice di rifrazione</translation>
    </message>
    <message>
        <source>Change volume</source>
        <translation>Cambia volume</translation>
    </message>
    <message>
        <source>Change alpha mode</source>
        <translation>Cambia modalità alfa</translation>
    </message>
    <message>
        <source>Change double sided</source>
        <translation>Cambia doppia faccia</translation>
    </message>
    <message>
        <source>Change texture</source>
        <translation>Cambia texture</translation>
    </message>
    <message>
        <source>Rename material</source>
        <translation>Rinomina materiale</translation>
    </message>
    <message>
        <source>Change bloom</source>
        <translation>Cambia bloom</translation>
    </message>
    <message>
        <source>New material</source>
        <translation>Nuovo materiale</translation>
    </message>
    <message>
        <source>Duplicate material</source>
        <translation>Duplica materiale</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Assegna materiale</translation>
    </message>
    <message>
        <source>Change motion blur</source>
        <translation>Modifica sfocatura di movimento</translation>
    </message>
    <message>
        <source>Change adaptive sampling</source>
        <translation>Cambia campionamento adattivo</translation>
    </message>
    <message>
        <source>Change fog</source>
        <translation>Cambia nebbia</translation>
    </message>
    <message>
        <source>Add studio environment</source>
        <translation>Aggiungi ambiente studio</translation>
    </message>
    <message>
        <source>Change sample blocks</source>
        <translation>Modifica blocchi di campioni</translation>
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
        <translation>La scena non ha ancora un nome di file: usa Salva con nome.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importa %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Senza titolo</translation>
    </message>
</context>
<context>
    <name>glint::editor::EditOperations</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>Nessuna selezione.</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Elimina</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplica</translation>
    </message>
    <message>
        <source>The node no longer exists.</source>
        <translation>Il nodo non esiste più.</translation>
    </message>
    <message>
        <source>A node cannot be moved into itself or its own children.</source>
        <translation>Un nodo non può essere spostato in sé stesso o nei propri figli.</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Cambia genitore</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Aggiungi %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::ExportDialog</name>
    <message>
        <source>Export image</source>
        <translation>Esporta immagine</translation>
    </message>
    <message>
        <source>Export animation</source>
        <translation>Esporta animazione</translation>
    </message>
    <message>
        <source>Output file</source>
        <translation>File di uscita</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
    <message>
        <source>Images (*.exr *.png *.jpg *.tif)</source>
        <translation>Immagini (*.exr *.png *.jpg *.tif)</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Uscita</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Larghezza</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Altezza</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Dimensione</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configurazione</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Campioni per pixel</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Seme</translation>
    </message>
    <message>
        <source>EXR layers</source>
        <translation>Livelli EXR</translation>
    </message>
    <message>
        <source>all, none, or a list of albedo, normal, depth, id, variance</source>
        <translation>all, none, oppure un elenco tra albedo, normal, depth, id, variance</translation>
    </message>
    <message>
        <source>Render passes</source>
        <translation>Passate di rendering</translation>
    </message>
    <message>
        <source>EXR only, Accumulate and Reference: none, all, light, or a list of DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</source>
        <translation>Solo EXR, Accumulate e Reference: none, all, light o un elenco di DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nessuna</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animazione</translation>
    </message>
    <message>
        <source>First frame</source>
        <translation>Primo fotogramma</translation>
    </message>
    <message>
        <source>Last frame</source>
        <translation>Ultimo fotogramma</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Fotogrammi</translation>
    </message>
    <message>
        <source>Video file</source>
        <translation>File video</translation>
    </message>
    <message>
        <source>optional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</source>
        <translation>facoltativo: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Video</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Esporta</translation>
    </message>
    <message>
        <source>Rendering...</source>
        <translation>Rendering in corso...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryModel</name>
    <message>
        <source>&lt;empty&gt;</source>
        <translation>&lt;vuoto&gt;</translation>
    </message>
    <message>
        <source> (saved)</source>
        <translation> (salvato)</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryPanel</name>
    <message>
        <source>Undo history</source>
        <translation>Cronologia annullamenti</translation>
    </message>
</context>
<context>
    <name>glint::editor::KeyedTransform</name>
    <message>
        <source>Transform and key</source>
        <translation>Trasforma e inserisci chiave</translation>
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
        <translation>Annulla</translation>
    </message>
    <message>
        <source>Stop reading the file; the open scene stays as it is</source>
        <translation>Interrompe la lettura del file; la scena aperta resta com'è</translation>
    </message>
    <message>
        <source>Loading progress</source>
        <translation>Avanzamento del caricamento</translation>
    </message>
</context>
<context>
    <name>glint::editor::LogPanel</name>
    <message>
        <source>Log messages</source>
        <translation>Messaggi del registro</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Svuota</translation>
    </message>
    <message>
        <source>Clear the log</source>
        <translation>Svuota il registro</translation>
    </message>
    <message>
        <source>info</source>
        <translation>info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>avviso</translation>
    </message>
    <message>
        <source>error</source>
        <translation>errore</translation>
    </message>
</context>
<context>
    <name>glint::editor::MainWindow</name>
    <message>
        <source>Glint scene editor</source>
        <translation>Editor di scene Glint</translation>
    </message>
    <message>
        <source>Scene to open</source>
        <translation>Scena da aprire</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Salvataggio automatico non riuscito: %1</translation>
    </message>
    <message>
        <source>The viewport is not available in this build.</source>
        <translation>La vista non è disponibile in questa build.</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Struttura</translation>
    </message>
    <message>
        <source>Undo history</source>
        <translation>Cronologia annullamenti</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scena</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <source>Nothing selected</source>
        <translation>Nessuna selezione</translation>
    </message>
    <message>
        <source>Selected: %1</source>
        <translation>Selezionato: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes selected</source>
        <translation><numerusform>%n nodo selezionato</numerusform><numerusform>%n nodi selezionati</numerusform></translation>
    </message>
    <message>
        <source>Selection</source>
        <translation>Selezione</translation>
    </message>
    <message>
        <source>Scene statistics</source>
        <translation>Statistiche della scena</translation>
    </message>
    <message>
        <source>Render progress</source>
        <translation>Avanzamento del rendering</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Modifiche non salvate</translation>
    </message>
    <message>
        <source>"%1" has unsaved changes. Save them first?</source>
        <translation>"%1" ha modifiche non salvate. Salvarle prima?</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>Impossibile aprire %1: %2</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Apri</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Aperto %1</translation>
    </message>
    <message>
        <source>Cannot import %1: %2</source>
        <translation>Impossibile importare %1: %2</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>Importato %1</translation>
    </message>
    <message>
        <source>Cannot save: %1</source>
        <translation>Impossibile salvare: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Salvato %1</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Salva scena</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb)</source>
        <translation>Scene glTF (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>Impossibile salvare %1: %2</translation>
    </message>
    <message>
        <source>an untitled scene</source>
        <translation>una scena senza titolo</translation>
    </message>
    <message>
        <source>Cannot recover the autosaved copy: %1</source>
        <translation>Impossibile recuperare la copia salvata automaticamente: %1</translation>
    </message>
    <message>
        <source>Recovered the autosaved copy of %1</source>
        <translation>Recuperata la copia salvata automaticamente di %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuovo</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Apri...</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Apri scena</translation>
    </message>
    <message>
        <source>Scenes (*.gltf *.glb *.glint.json);;All files (*)</source>
        <translation>Scene (*.gltf *.glb *.glint.json);;Tutti i file (*)</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importa...</translation>
    </message>
    <message>
        <source>Import into the scene</source>
        <translation>Importa nella scena</translation>
    </message>
    <message>
        <source>Scenes and models (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;All files (*)</source>
        <translation>Scene e modelli (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;Tutti i file (*)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Salva</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Salva &amp;con nome...</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Preferenze...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annulla</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Ripeti</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Elimina</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>D&amp;uplica</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Seleziona &amp;tutto</translation>
    </message>
    <message>
        <source>Select &amp;None</source>
        <translation>&amp;Deseleziona tutto</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Apri &amp;recenti</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Modifica</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Pannelli</translation>
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
        <translation>Luce</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Scuro</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <source>&amp;About Glint</source>
        <translation>&amp;Informazioni su Glint</translation>
    </message>
    <message>
        <source>About Glint</source>
        <translation>Informazioni su Glint</translation>
    </message>
    <message>
        <source>Glint %1: a scene editor with a built-in OpenGL 4.1 path tracer.</source>
        <translation>Glint %1: un editor di scene con un path tracer OpenGL 4.1 integrato.</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Informazioni su &amp;Qt</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Barra degli strumenti principale</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>View toolbar</source>
        <translation>Barra degli strumenti della vista</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Svuota l'elenco</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annulla %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Ripeti %1</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Timeline</translation>
    </message>
    <message>
        <source>Export &amp;Image...</source>
        <translation>Esporta &amp;immagine...</translation>
    </message>
    <message>
        <source>Export A&amp;nimation...</source>
        <translation>Esporta a&amp;nimazione...</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Apertura di %1</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importazione di %1</translation>
    </message>
    <message>
        <source>Recovering an untitled scene</source>
        <translation>Recupero di una scena senza titolo</translation>
    </message>
    <message>
        <source>Recovering %1</source>
        <translation>Recupero di %1</translation>
    </message>
    <message>
        <source>Cannot open %1:
%2</source>
        <translation>Impossibile aprire %1:
%2</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Importazione di %1 annullata</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>Apertura di %1 annullata</translation>
    </message>
    <message>
        <source>This display gives no OpenGL 4.1 core context, so the editor opens without its viewport; `glint render` renders headless (EGL).</source>
        <translation>Questo display non offre un contesto OpenGL 4.1 core, perciò l'editor si apre senza la vista; `glint render` esegue il rendering senza display (EGL).</translation>
    </message>
    <message>
        <source>%1, %2, configuration: %3</source>
        <translation>%1, %2, configurazione: %3</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes</source>
        <translation><numerusform>%n nodo</numerusform><numerusform>%n nodi</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n triangles</source>
        <translation><numerusform>%n triangolo</numerusform><numerusform>%n triangoli</numerusform></translation>
    </message>
    <message>
        <source>%1 (autosaved %2)</source>
        <translation>%1 (salvato automaticamente %2)</translation>
    </message>
    <message>
        <source>Discard all autosaved copies</source>
        <translation>Scarta tutte le copie salvate automaticamente</translation>
    </message>
    <message>
        <source>Nothing to recover</source>
        <translation>Niente da recuperare</translation>
    </message>
    <message>
        <source>Glint did not close normally: the copy of %1 autosaved at %2 is newer than the file.</source>
        <translation>Glint non si è chiuso normalmente: la copia di %1 salvata automaticamente alle %2 è più recente del file.</translation>
    </message>
    <message>
        <source>Glint did not close normally: unsaved work on %1 was autosaved at %2.</source>
        <translation>Glint non si è chiuso normalmente: il lavoro non salvato su %1 è stato salvato automaticamente alle %2.</translation>
    </message>
    <message numerus="yes">
        <source>%n more in File &gt; Recover.</source>
        <translation><numerusform>Un'altra in File &gt; Recupera.</numerusform><numerusform>Altre %n in File &gt; Recupera.</numerusform></translation>
    </message>
    <message>
        <source>Re&amp;cover</source>
        <translation>Re&amp;cupera</translation>
    </message>
    <message>
        <source>There are no meshes in %1: nothing to import.</source>
        <translation>In %1 non ci sono mesh: niente da importare.</translation>
    </message>
    <message>
        <source>%1 holds a mesh without any faces, so it cannot be imported.</source>
        <translation>%1 contiene una mesh senza facce, quindi non può essere importato.</translation>
    </message>
    <message>
        <source>%1 is in no format Glint imports (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</source>
        <translation>%1 non è in un formato che Glint importa (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</translation>
    </message>
    <message>
        <source>%1 ends too early: the file is damaged or was not copied completely.</source>
        <translation>%1 finisce troppo presto: il file è danneggiato o non è stato copiato del tutto.</translation>
    </message>
    <message>
        <source>%1 cannot be read.</source>
        <translation>%1 non può essere letto.</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 è vuoto.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importa</translation>
    </message>
    <message>
        <source>Cannot import %1:
%2</source>
        <translation>Impossibile importare %1:
%2</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiali</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Nuova scena</translation>
    </message>
    <message>
        <source>New from &amp;template</source>
        <translation>Nuova da &amp;modello</translation>
    </message>
    <message>
        <source>%1 (autosaved %2, older than the file)</source>
        <translation>%1 (salvato automaticamente %2, più vecchio del file)</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialListModel</name>
    <message>
        <source>Material %1</source>
        <translation>Materiale %1</translation>
    </message>
    <message>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message numerus="yes">
        <source>%n users</source>
        <translation><numerusform>%n utente</numerusform><numerusform>%n utenti</numerusform></translation>
    </message>
    <message>
        <source>%1: no node uses it (Delete unused removes it)</source>
        <translation>%1: nessun nodo lo usa (Elimina inutilizzati lo rimuove)</translation>
    </message>
    <message>
        <source>%1: drag it onto a node in the outliner or the viewport to assign it</source>
        <translation>%1: trascinalo su un nodo nella struttura o nella vista per assegnarlo</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialPresets</name>
    <message>
        <source>Plastic</source>
        <translation>Plastica</translation>
    </message>
    <message>
        <source>Rough</source>
        <translation>Ruvido</translation>
    </message>
    <message>
        <source>Glossy (clear coat)</source>
        <translation>Lucido (vernice trasparente)</translation>
    </message>
    <message>
        <source>Metal</source>
        <translation>Metallo</translation>
    </message>
    <message>
        <source>Gold</source>
        <translation>Oro</translation>
    </message>
    <message>
        <source>Brushed metal</source>
        <translation>Metallo spazzolato</translation>
    </message>
    <message>
        <source>Glass</source>
        <translation>Vetro</translation>
    </message>
    <message>
        <source>Frosted glass</source>
        <translation>Vetro satinato</translation>
    </message>
    <message>
        <source>Emitter</source>
        <translation>Emettitore</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialsPanel</name>
    <message>
        <source>Search materials</source>
        <translation>Cerca materiali</translation>
    </message>
    <message>
        <source>Material search</source>
        <translation>Ricerca materiali</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiali</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nuovo</translation>
    </message>
    <message>
        <source>A new material from a preset</source>
        <translation>Un nuovo materiale da un preset</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplica</translation>
    </message>
    <message>
        <source>A copy of the selected material</source>
        <translation>Una copia del materiale selezionato</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Rinomina</translation>
    </message>
    <message>
        <source>Rename the selected material</source>
        <translation>Rinomina il materiale selezionato</translation>
    </message>
    <message>
        <source>Delete unused</source>
        <translation>Elimina inutilizzati</translation>
    </message>
    <message>
        <source>Remove every material no node uses</source>
        <translation>Rimuove ogni materiale che nessun nodo usa</translation>
    </message>
    <message>
        <source>Assign to selection</source>
        <translation>Assegna alla selezione</translation>
    </message>
    <message>
        <source>Give the selected material to every selected shape and mesh (one undo step)</source>
        <translation>Assegna il materiale selezionato a ogni forma e mesh selezionata (un solo passo di annullamento)</translation>
    </message>
    <message numerus="yes">
        <source>%n unused materials removed.</source>
        <translation><numerusform>%n materiale inutilizzato rimosso.</numerusform><numerusform>%n materiali inutilizzati rimossi.</numerusform></translation>
    </message>
    <message>
        <source>Select a material in the list first.</source>
        <translation>Seleziona prima un materiale nell'elenco.</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeKeyTracks</name>
    <message>
        <source>Node keys</source>
        <translation>Chiavi dei nodi</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeNames</name>
    <message>
        <source>Sphere %1</source>
        <translation>Sfera %1</translation>
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
        <translation>Cubo %1</translation>
    </message>
    <message>
        <source>Cylinder %1</source>
        <translation>Cilindro %1</translation>
    </message>
    <message>
        <source>Ground plane %1</source>
        <translation>Piano del terreno %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Nodo %1</translation>
    </message>
    <message>
        <source>Sun %1</source>
        <translation>Sole %1</translation>
    </message>
    <message>
        <source>Point light %1</source>
        <translation>Luce puntiforme %1</translation>
    </message>
    <message>
        <source>Spot light %1</source>
        <translation>Faretto %1</translation>
    </message>
    <message>
        <source>Mesh %1</source>
        <translation>Mesh %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Camera %1</translation>
    </message>
    <message>
        <source>Area light %1</source>
        <translation>Luce d'area %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerModel</name>
    <message>
        <source>Mesh</source>
        <translation>Mesh</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luce</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppo</translation>
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
        <translation>Visibile</translation>
    </message>
    <message>
        <source>Hidden</source>
        <translation>Nascosto</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <source>%1 (%2; the file gives it no name)</source>
        <translation>%1 (%2; il file non gli dà un nome)</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerPanel</name>
    <message>
        <source>Filter by name</source>
        <translation>Filtra per nome</translation>
    </message>
    <message>
        <source>Outliner filter</source>
        <translation>Filtro della struttura</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Aggiungi</translation>
    </message>
    <message>
        <source>Add a shape, light or camera</source>
        <translation>Aggiungi una forma, una luce o una camera</translation>
    </message>
    <message>
        <source>Scene outliner</source>
        <translation>Struttura della scena</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Sfera</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Parallelepipedo</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Quadrilatero</translation>
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
        <translation>Piano del terreno</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luce</translation>
    </message>
    <message>
        <source>Point light</source>
        <translation>Luce puntiforme</translation>
    </message>
    <message>
        <source>Spot light</source>
        <translation>Faretto</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Sole</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <source>Empty group</source>
        <translation>Gruppo vuoto</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Rinomina</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplica</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Elimina</translation>
    </message>
    <message>
        <source>Area rectangle</source>
        <translation>Rettangolo d'area</translation>
    </message>
    <message>
        <source>Area disk</source>
        <translation>Disco d'area</translation>
    </message>
    <message>
        <source>Area sphere</source>
        <translation>Sfera d'area</translation>
    </message>
    <message>
        <source>Portal pair</source>
        <translation>Coppia di portali</translation>
    </message>
    <message>
        <source>Studio environment</source>
        <translation>Ambiente studio</translation>
    </message>
</context>
<context>
    <name>glint::editor::PortalEdits</name>
    <message>
        <source>Add Portal Pair</source>
        <translation>Aggiungi coppia di portali</translation>
    </message>
    <message>
        <source>Portal A</source>
        <translation>Portale A</translation>
    </message>
    <message>
        <source>Portal B</source>
        <translation>Portale B</translation>
    </message>
    <message>
        <source>Only a quad can be a portal.</source>
        <translation>Solo un quadrilatero può essere un portale.</translation>
    </message>
    <message>
        <source>A portal cannot lead to itself.</source>
        <translation>Un portale non può condurre a se stesso.</translation>
    </message>
    <message>
        <source>A portal can only lead to another quad.</source>
        <translation>Un portale può condurre solo a un altro quadrilatero.</translation>
    </message>
    <message>
        <source>Link Portals</source>
        <translation>Collega portali</translation>
    </message>
    <message>
        <source>Unlink Portal</source>
        <translation>Scollega portale</translation>
    </message>
</context>
<context>
    <name>glint::editor::Preferences</name>
    <message>
        <source>System language</source>
        <translation>Lingua di sistema</translation>
    </message>
</context>
<context>
    <name>glint::editor::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Preferenze</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Generale</translation>
    </message>
    <message>
        <source>Keymap</source>
        <translation>Scorciatoie</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luce</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Scuro</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Tema</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Lingua</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Disattivato</translation>
    </message>
    <message>
        <source>Autosave interval</source>
        <translation>Intervallo di salvataggio automatico</translation>
    </message>
    <message>
        <source>Autosave every</source>
        <translation>Salvataggio automatico ogni</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Comando</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Scorciatoia</translation>
    </message>
    <message>
        <source>Shortcut for %1</source>
        <translation>Scorciatoia per %1</translation>
    </message>
    <message>
        <source>Shortcut conflict</source>
        <translation>Conflitto di scorciatoie</translation>
    </message>
    <message>
        <source>%1 is used by both "%2" and "%3".</source>
        <translation>%1 è usata sia da "%2" sia da "%3".</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Nessun limite</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Campioni della vista</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here (renders use the Scene panel's samples)</source>
        <translation>La vista smette di aggiungere campioni per pixel qui (i render usano i campioni del pannello Scena)</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Predefinita</translation>
    </message>
    <message>
        <source>Reset all to defaults</source>
        <translation>Ripristina tutte le predefinite</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertiesPanel</name>
    <message>
        <source>Scene settings</source>
        <translation>Impostazioni della scena</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <source>Select a node in the outliner or the viewport to edit it.</source>
        <translation>Seleziona un nodo nella struttura o nella vista per modificarlo.</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyEdits</name>
    <message>
        <source>Edit %1 nodes</source>
        <translation>Modifica %1 nodi</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyForm</name>
    <message>
        <source>Texture %1</source>
        <translation>Texture %1</translation>
    </message>
    <message>
        <source>%1 thumbnail</source>
        <translation>Miniatura di %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(nessuna)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>senza nome</translation>
    </message>
    <message>
        <source>Material: %1</source>
        <translation>Materiale: %1</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>Colore di base</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Opacità</translation>
    </message>
    <message>
        <source>Base colour texture</source>
        <translation>Texture del colore di base</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Metallicità</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rugosità</translation>
    </message>
    <message>
        <source>Metallic-roughness texture</source>
        <translation>Texture metallicità-rugosità</translation>
    </message>
    <message>
        <source>Normal texture</source>
        <translation>Texture delle normali</translation>
    </message>
    <message>
        <source>Occlusion texture</source>
        <translation>Texture di occlusione</translation>
    </message>
    <message>
        <source>Emission</source>
        <translation>Emissione</translation>
    </message>
    <message>
        <source>Emission strength</source>
        <translation>Intensità di emissione</translation>
    </message>
    <message>
        <source>Emission texture</source>
        <translation>Texture di emissione</translation>
    </message>
    <message>
        <source>Specular</source>
        <translation>Speculare</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>Colore speculare</translation>
    </message>
    <message>
        <source>Specular texture</source>
        <translation>Texture speculare</translation>
    </message>
    <message>
        <source>Specular colour texture</source>
        <translation>Texture del colore speculare</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>Trasmissione</translation>
    </message>
    <message>
        <source>Transmission texture</source>
        <translation>Texture di trasmissione</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>Indice di rifrazione</translation>
    </message>
    <message>
        <source>Thickness</source>
        <translation>Spessore</translation>
    </message>
    <message>
        <source>Thickness texture</source>
        <translation>Texture dello spessore</translation>
    </message>
    <message>
        <source>Attenuation distance (m)</source>
        <translation>Distanza di attenuazione (m)</translation>
    </message>
    <message>
        <source>Attenuation colour</source>
        <translation>Colore di attenuazione</translation>
    </message>
    <message>
        <source>Alpha mode</source>
        <translation>Modalità alfa</translation>
    </message>
    <message>
        <source>Opaque</source>
        <translation>Opaco</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Maschera</translation>
    </message>
    <message>
        <source>Blend</source>
        <translation>Fusione</translation>
    </message>
    <message>
        <source>Alpha cutoff</source>
        <translation>Soglia alfa</translation>
    </message>
    <message>
        <source>Double sided</source>
        <translation>Doppia faccia</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Nodo</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Visibile</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Trasformazione</translation>
    </message>
    <message>
        <source>Position %1</source>
        <translation>Posizione %1</translation>
    </message>
    <message>
        <source>Rotation %1 (degrees)</source>
        <translation>Rotazione %1 (gradi)</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <translation>Scala %1</translation>
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
        <translation>Sfera</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Quadrilatero</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Disco</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Parallelepipedo</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Cilindro</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Piano del terreno</translation>
    </message>
    <message>
        <source>Radius (m)</source>
        <translation>Raggio (m)</translation>
    </message>
    <message>
        <source>Height (m)</source>
        <translation>Altezza (m)</translation>
    </message>
    <message>
        <source>Size %1 (m)</source>
        <translation>Dimensione %1 (m)</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luce</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Sole</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Puntiforme</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Faretto</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Colore</translation>
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
        <translation>unità Blender</translation>
    </message>
    <message>
        <source>raw units</source>
        <translation>unità grezze</translation>
    </message>
    <message>
        <source>Intensity (%1, %2)</source>
        <translation>Intensità (%1, %2)</translation>
    </message>
    <message>
        <source>Range (m, 0 = infinite)</source>
        <translation>Portata (m, 0 = infinita)</translation>
    </message>
    <message>
        <source>Inner cone (degrees)</source>
        <translation>Cono interno (gradi)</translation>
    </message>
    <message>
        <source>Outer cone (degrees)</source>
        <translation>Cono esterno (gradi)</translation>
    </message>
    <message>
        <source>Sun angular diameter (degrees)</source>
        <translation>Diametro angolare del sole (gradi)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <source>Projection</source>
        <translation>Proiezione</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Prospettica</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <translation>Ortografica</translation>
    </message>
    <message>
        <source>Vertical field of view (degrees)</source>
        <translation>Campo visivo verticale (gradi)</translation>
    </message>
    <message>
        <source>Lens radius (m)</source>
        <translation>Raggio dell'obiettivo (m)</translation>
    </message>
    <message>
        <source>Focus distance (m)</source>
        <translation>Distanza di messa a fuoco (m)</translation>
    </message>
    <message>
        <source>Exposure (EV)</source>
        <translation>Esposizione (EV)</translation>
    </message>
    <message>
        <source>Near clip (m)</source>
        <translation>Piano di taglio vicino (m)</translation>
    </message>
    <message>
        <source>Active camera</source>
        <translation>Camera attiva</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Ambiente</translation>
    </message>
    <message>
        <source>HDR file</source>
        <translation>File HDR</translation>
    </message>
    <message>
        <source>Colour (no file)</source>
        <translation>Colore (senza file)</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensità</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>Rotazione (gradi)</translation>
    </message>
    <message>
        <source>Render settings</source>
        <translation>Impostazioni di rendering</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configurazione</translation>
    </message>
    <message>
        <source>Width (px)</source>
        <translation>Larghezza (px)</translation>
    </message>
    <message>
        <source>Height (px)</source>
        <translation>Altezza (px)</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Campioni per pixel</translation>
    </message>
    <message>
        <source>Bounces</source>
        <translation>Rimbalzi</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Seme</translation>
    </message>
    <message>
        <source>Tonemapper</source>
        <translation>Tone mapping</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Nessuno</translation>
    </message>
    <message>
        <source>ACES (fitted)</source>
        <translation>ACES (approssimato)</translation>
    </message>
    <message>
        <source>Khronos PBR Neutral</source>
        <translation>Khronos PBR Neutral</translation>
    </message>
    <message>
        <source>Radiance clamp (0 = off)</source>
        <translation>Limite di radianza (0 = disattivato)</translation>
    </message>
    <message>
        <source>Light units</source>
        <translation>Unità di luce</translation>
    </message>
    <message>
        <source>Blender (W = lm / 683)</source>
        <translation>Blender (W = lm / 683)</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Grezze</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
    <message>
        <source>Choose an HDR environment file</source>
        <translation>Scegli un file d'ambiente HDR</translation>
    </message>
    <message>
        <source>Environment map</source>
        <translation>Mappa d'ambiente</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>Immagini HDR (*.hdr *.exr);;Tutti i file (*)</translation>
    </message>
    <message>
        <source>Camera and timeline</source>
        <translation>Camera e timeline</translation>
    </message>
    <message>
        <source>(the first camera)</source>
        <translation>(la prima camera)</translation>
    </message>
    <message>
        <source>Timeline start (s)</source>
        <translation>Inizio timeline (s)</translation>
    </message>
    <message>
        <source>Timeline end (s, 0 = the animation's)</source>
        <translation>Fine timeline (s, 0 = quella dell'animazione)</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Fotogrammi al secondo</translation>
    </message>
    <message>
        <source>Frames per second must be a positive number or a ratio such as 24000/1001, not "%1".</source>
        <translation>I fotogrammi al secondo devono essere un numero positivo o un rapporto come 24000/1001, non "%1".</translation>
    </message>
    <message>
        <source>Real-time reconstruction</source>
        <translation>Ricostruzione in tempo reale</translation>
    </message>
    <message>
        <source>TAA blend (current frame)</source>
        <translation>Fusione TAA (fotogramma attuale)</translation>
    </message>
    <message>
        <source>TAA clip box (std. deviations)</source>
        <translation>Box di clipping TAA (deviazioni std.)</translation>
    </message>
    <message>
        <source>TAA perceptual blend</source>
        <translation>Fusione percettiva TAA</translation>
    </message>
    <message>
        <source>SVGF a-trous iterations</source>
        <translation>Iterazioni à-trous SVGF</translation>
    </message>
    <message>
        <source>SVGF temporal alpha</source>
        <translation>Alfa temporale SVGF</translation>
    </message>
    <message>
        <source>SVGF moments alpha</source>
        <translation>Alfa dei momenti SVGF</translation>
    </message>
    <message>
        <source>SVGF luminance sigma</source>
        <translation>Sigma di luminanza SVGF</translation>
    </message>
    <message>
        <source>SVGF normal sigma (exponent)</source>
        <translation>Sigma delle normali SVGF (esponente)</translation>
    </message>
    <message>
        <source>SVGF depth sigma</source>
        <translation>Sigma di profondità SVGF</translation>
    </message>
    <message>
        <source>SVGF firefly ratio</source>
        <translation>Rapporto lucciole SVGF</translation>
    </message>
    <message>
        <source>TAA history clipping</source>
        <translation>Clipping della storia TAA</translation>
    </message>
    <message>
        <source>Variance clip (YCoCg)</source>
        <translation>Clipping di varianza (YCoCg)</translation>
    </message>
    <message>
        <source>Min/max clamp</source>
        <translation>Limitazione min/max</translation>
    </message>
    <message>
        <source>None (ghosts)</source>
        <translation>Nessuna (scie)</translation>
    </message>
    <message>
        <source>"%1" is relative, but the scene has no folder yet: choose the file with Browse, or save the scene first.</source>
        <translation>"%1" è relativo, ma la scena non ha ancora una cartella: scegli il file con Sfoglia, oppure salva prima la scena.</translation>
    </message>
    <message>
        <source>Cannot read the environment image %1. Choose it again with Browse, or clear the field to use the colour below.</source>
        <translation>Impossibile leggere l'immagine d'ambiente %1. Sceglila di nuovo con Sfoglia, oppure svuota il campo per usare il colore qui sotto.</translation>
    </message>
    <message>
        <source>Environment image status</source>
        <translation>Stato dell'immagine d'ambiente</translation>
    </message>
    <message>
        <source>An infinite plane: the node's y = 0, facing +Y; move and turn it with the transform. It has no size. In the glTF file other programs (Blender) get a 200 m square in its place.</source>
        <translation>Un piano infinito: y = 0 del nodo, rivolto verso +Y; spostalo e ruotalo con la trasformazione. Non ha dimensioni. Nel file glTF gli altri programmi (Blender) ricevono al suo posto un quadrato di 200 m.</translation>
    </message>
    <message>
        <source>Half height (m)</source>
        <translation>Semialtezza (m)</translation>
    </message>
    <message>
        <source>AgX</source>
        <translation>AgX</translation>
    </message>
    <message>
        <source>Reinhard (extended)</source>
        <translation>Reinhard (esteso)</translation>
    </message>
    <message>
        <source>Hable (Uncharted 2)</source>
        <translation>Hable (Uncharted 2)</translation>
    </message>
    <message>
        <source>Bloom strength (0 = off)</source>
        <translation>Intensità del bloom (0 = spento)</translation>
    </message>
    <message>
        <source>Bloom radius (of the height)</source>
        <translation>Raggio del bloom (rispetto all'altezza)</translation>
    </message>
    <message>
        <source>Edit sampler</source>
        <translation>Modifica campionatore</translation>
    </message>
    <message>
        <source>Load texture</source>
        <translation>Carica texture</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</source>
        <translation>Immagini (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Carica…</translation>
    </message>
    <message>
        <source>Load an image file (PNG, JPEG, EXR, HDR, TIFF) into this slot</source>
        <translation>Carica un file immagine (PNG, JPEG, EXR, HDR, TIFF) in questo slot</translation>
    </message>
    <message>
        <source>Load %1</source>
        <translation>Carica %1</translation>
    </message>
    <message>
        <source>UV set</source>
        <translation>Set UV</translation>
    </message>
    <message>
        <source>Repeat</source>
        <translation>Ripeti</translation>
    </message>
    <message>
        <source>Clamp to edge</source>
        <translation>Blocca al bordo</translation>
    </message>
    <message>
        <source>Mirrored repeat</source>
        <translation>Ripetizione speculare</translation>
    </message>
    <message>
        <source>Wrap U</source>
        <translation>Ripetizione U</translation>
    </message>
    <message>
        <source>Wrap V</source>
        <translation>Ripetizione V</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filtro</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineare</translation>
    </message>
    <message>
        <source>Nearest</source>
        <translation>Più vicino</translation>
    </message>
    <message>
        <source>Offset U</source>
        <translation>Offset U</translation>
    </message>
    <message>
        <source>Offset V</source>
        <translation>Offset V</translation>
    </message>
    <message>
        <source>Scale U</source>
        <translation>Scala U</translation>
    </message>
    <message>
        <source>Scale V</source>
        <translation>Scala V</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiali</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Modifica</translation>
    </message>
    <message>
        <source>Show this primitive's material below</source>
        <translation>Mostra sotto il materiale di questa primitiva</translation>
    </message>
    <message numerus="yes">
        <source>Primitive %1 (%n triangles)</source>
        <translation><numerusform>Primitiva %1 (%n triangolo)</numerusform><numerusform>Primitiva %1 (%n triangoli)</numerusform></translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Materiale</translation>
    </message>
    <message>
        <source>(default)</source>
        <translation>(predefinito)</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>Materiale %1</translation>
    </message>
    <message>
        <source>Motion blur shutter (frames, 0 = off)</source>
        <translation>Otturatore sfocatura di movimento (fotogrammi, 0 = spento)</translation>
    </message>
    <message>
        <source>Rectangle</source>
        <translation>Rettangolo</translation>
    </message>
    <message>
        <source>Power (W)</source>
        <translation>Potenza (W)</translation>
    </message>
    <message>
        <source>Size X (m)</source>
        <translation>Dimensione X (m)</translation>
    </message>
    <message>
        <source>Size Y (m)</source>
        <translation>Dimensione Y (m)</translation>
    </message>
    <message>
        <source>Diameter (m)</source>
        <translation>Diametro (m)</translation>
    </message>
    <message>
        <source>Emits its power evenly from the front face (the light's -Z) of the rectangle or disk, or the outside of the sphere; in the glTF file other programs get an emissive mesh.</source>
        <translation>Emette la sua potenza uniformemente dalla faccia anteriore (il -Z della luce) del rettangolo o del disco, o dall'esterno della sfera; nel file glTF gli altri programmi ricevono una mesh emissiva.</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Area</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Campioni della vista</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Nessun limite</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here; renders use the samples per pixel above</source>
        <translation>La vista smette di aggiungere campioni per pixel qui; i render usano i campioni per pixel sopra</translation>
    </message>
    <message>
        <source>Rendering</source>
        <translation>Rendering</translation>
    </message>
    <message>
        <source>Noise threshold (adaptive sampling, 0 = off)</source>
        <translation>Soglia di rumore (campionamento adattivo, 0 = disattivato)</translation>
    </message>
    <message>
        <source>Adaptive minimum samples (0 = automatic)</source>
        <translation>Campioni minimi adattivi (0 = automatico)</translation>
    </message>
    <message>
        <source>Scatter anisotropy</source>
        <translation>Anisotropia di diffusione</translation>
    </message>
    <message>
        <source>Scatter colour</source>
        <translation>Colore di diffusione</translation>
    </message>
    <message>
        <source>Fog</source>
        <translation>Nebbia</translation>
    </message>
    <message>
        <source>Density (1/m)</source>
        <translation>Densità (1/m)</translation>
    </message>
    <message>
        <source>Anisotropy</source>
        <translation>Anisotropia</translation>
    </message>
    <message>
        <source>Height falloff (1/m)</source>
        <translation>Attenuazione con l'altezza (1/m)</translation>
    </message>
    <message>
        <source>Base height (m)</source>
        <translation>Altezza di base (m)</translation>
    </message>
    <message>
        <source>node %1, deleted</source>
        <translation>nodo %1, eliminato</translation>
    </message>
    <message>
        <source>Not paired: the other side does not lead back here, so this quad is an ordinary surface. Choose a quad to pair them again.</source>
        <translation>Non accoppiato: l'altro lato non riconduce qui, quindi questo quadrilatero è una superficie normale. Scegli un quadrilatero per accoppiarli di nuovo.</translation>
    </message>
    <message>
        <source>What enters this quad leaves the quad chosen here, and the other way round.</source>
        <translation>Ciò che entra in questo quadrilatero esce dal quadrilatero scelto qui, e viceversa.</translation>
    </message>
    <message>
        <source>Portal to</source>
        <translation>Portale verso</translation>
    </message>
    <message>
        <source>Adaptive goal</source>
        <translation>Obiettivo adattivo</translation>
    </message>
    <message>
        <source>Even noise (as Cycles)</source>
        <translation>Rumore uniforme (come Cycles)</translation>
    </message>
    <message>
        <source>Least mean error</source>
        <translation>Errore medio minimo</translation>
    </message>
    <message>
        <source>Sample blocks (pixels sharing a sequence)</source>
        <translation>Blocchi di campioni (pixel con una sequenza comune)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Disattivato</translation>
    </message>
</context>
<context>
    <name>glint::editor::RecoveryBar</name>
    <message>
        <source>Recover unsaved work</source>
        <translation>Recupera il lavoro non salvato</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Recupera</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Scarta</translation>
    </message>
    <message>
        <source>Delete the autosaved copy</source>
        <translation>Elimina la copia salvata automaticamente</translation>
    </message>
    <message>
        <source>Later (File &gt; Recover keeps it)</source>
        <translation>Più tardi (resta in File &gt; Recupera)</translation>
    </message>
    <message>
        <source>Hide</source>
        <translation>Nascondi</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderHost</name>
    <message>
        <source>Preparing the scene</source>
        <translation>Preparazione della scena</translation>
    </message>
    <message>
        <source>building mesh BVHs</source>
        <translation>costruzione dei BVH delle mesh</translation>
    </message>
    <message>
        <source>decoding textures</source>
        <translation>decodifica delle texture</translation>
    </message>
    <message>
        <source>loading the environment</source>
        <translation>caricamento dell'ambiente</translation>
    </message>
    <message>
        <source>packing the scene</source>
        <translation>impacchettamento della scena</translation>
    </message>
    <message>
        <source>building the click picker</source>
        <translation>costruzione del selettore per clic</translation>
    </message>
    <message>
        <source>Preparing the scene: %1 %2/%3</source>
        <translation>Preparazione della scena: %1 %2/%3</translation>
    </message>
    <message>
        <source>Preparing the scene: %1</source>
        <translation>Preparazione della scena: %1</translation>
    </message>
    <message>
        <source>Nothing in the scene emits light, so the path-traced image is black: add a light (Add &gt; Light &gt; Studio environment lights any model) or an emissive material, or give the environment a colour or an image (Scene tab).</source>
        <translation>Nella scena nulla emette luce, perciò l'immagine path-traced è nera: aggiungi una luce (Aggiungi &gt; Luce &gt; Ambiente studio illumina qualsiasi modello) o un materiale emissivo, oppure dai all'ambiente un colore o un'immagine (scheda Scena).</translation>
    </message>
    <message>
        <source>Only emissive textures give light in this scene, so most of the path-traced image is dark: add a light (Add &gt; Light &gt; Studio environment lights any model), or give the environment a colour or an image (Scene tab).</source>
        <translation>In questa scena solo le texture emissive danno luce, perciò gran parte dell'immagine path-traced è scura: aggiungi una luce (Aggiungi &gt; Luce &gt; Ambiente studio illumina qualsiasi modello), oppure dai all'ambiente un colore o un'immagine (scheda Scena).</translation>
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
        <translation>Pixel %1, %2
R %3  G %4  B %5 (lineare)</translation>
    </message>
</context>
<context>
    <name>glint::editor::SceneLoader</name>
    <message>
        <source>reading the glTF file</source>
        <translation>lettura del file glTF</translation>
    </message>
    <message>
        <source>running the importer</source>
        <translation>esecuzione dell'importatore</translation>
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
        <translation>Vuota</translation>
    </message>
    <message>
        <source>Sun and sky</source>
        <translation>Sole e cielo</translation>
    </message>
    <message>
        <source>Cornell box</source>
        <translation>Cornell box</translation>
    </message>
    <message>
        <source>Cornell box in fog</source>
        <translation>Cornell box nella nebbia</translation>
    </message>
    <message>
        <source>Portals</source>
        <translation>Portali</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimeRuler</name>
    <message>
        <source>Time ruler</source>
        <translation>Righello temporale</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimelinePanel</name>
    <message>
        <source>Timeline</source>
        <translation>Timeline</translation>
    </message>
    <message>
        <source>Path camera</source>
        <translation>Camera del percorso</translation>
    </message>
    <message>
        <source>  %1 s  (frame %2)</source>
        <translation>  %1 s  (fotogramma %2)</translation>
    </message>
    <message>
        <source>Add key</source>
        <translation>Aggiungi chiave</translation>
    </message>
    <message>
        <source>Add a camera-path key from the current view at the current time</source>
        <translation>Aggiunge una chiave del percorso della camera dalla vista attuale all'istante attuale</translation>
    </message>
    <message>
        <source>Delete key</source>
        <translation>Elimina chiave</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Riproduci</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>Constant speed</source>
        <translation>Velocità costante</translation>
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
        <translation>Campo visivo</translation>
    </message>
    <message>
        <source>Focus</source>
        <translation>Fuoco</translation>
    </message>
    <message>
        <source>Lens</source>
        <translation>Obiettivo</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>Key %1</source>
        <translation>Chiave %1</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineare</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Chiave trasformazione</translation>
    </message>
    <message>
        <source>Key the selected nodes' position, rotation and scale at the current time (K)</source>
        <translation>Inserisce una chiave per posizione, rotazione e scala dei nodi selezionati all'istante attuale (K)</translation>
    </message>
    <message>
        <source>Copy key</source>
        <translation>Copia chiave</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Incolla chiave</translation>
    </message>
    <message>
        <source>Key the selected nodes at the current time with the copied key's transform</source>
        <translation>Inserisce una chiave per i nodi selezionati all'istante attuale con la trasformazione della chiave copiata</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>Interpolazione</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>A gradini</translation>
    </message>
    <message>
        <source>Cubic</source>
        <translation>Cubica</translation>
    </message>
    <message>
        <source>Auto key</source>
        <translation>Chiave automatica</translation>
    </message>
    <message>
        <source>Key every moved, turned or scaled node at the current time (nodes with keys are always keyed)</source>
        <translation>Inserisce una chiave per ogni nodo spostato, ruotato o scalato al tempo corrente (i nodi con chiavi ne ricevono sempre una)</translation>
    </message>
</context>
<context>
    <name>glint::editor::Viewport</name>
    <message>
        <source>Path traced</source>
        <translation>Path tracing</translation>
    </message>
    <message>
        <source>Solid</source>
        <translation>Solido</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>Wireframe</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normali</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <source>Ambient occlusion</source>
        <translation>Occlusione ambientale</translation>
    </message>
    <message>
        <source>Motion vectors</source>
        <translation>Vettori di movimento</translation>
    </message>
    <message>
        <source>Variance</source>
        <translation>Varianza</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Profondità</translation>
    </message>
    <message>
        <source>BVH instance boxes</source>
        <translation>Riquadri BVH delle istanze</translation>
    </message>
    <message>
        <source>BVH traversal cost (heat map)</source>
        <translation>Costo di attraversamento BVH (mappa di calore)</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vista</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Sposta</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Ruota</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Scala</translation>
    </message>
    <message>
        <source>Frame selection</source>
        <translation>Inquadra selezione</translation>
    </message>
    <message>
        <source>Make scene camera from view</source>
        <translation>Crea camera della scena dalla vista</translation>
    </message>
    <message>
        <source>Look through selected camera</source>
        <translation>Guarda dalla camera selezionata</translation>
    </message>
    <message>
        <source>Snap (Ctrl inverts while dragging)</source>
        <translation>Aggancio (Ctrl inverte durante il trascinamento)</translation>
    </message>
    <message>
        <source>Pixel inspector</source>
        <translation>Ispettore pixel</translation>
    </message>
    <message>
        <source>Take snapshot A</source>
        <translation>Cattura istantanea A</translation>
    </message>
    <message>
        <source>Set render region</source>
        <translation>Imposta regione di rendering</translation>
    </message>
    <message>
        <source>Drag a rectangle: the path tracer renders only inside it</source>
        <translation>Trascina un rettangolo: il path tracer renderizza solo al suo interno</translation>
    </message>
    <message>
        <source>Clear render region</source>
        <translation>Cancella regione di rendering</translation>
    </message>
    <message>
        <source>Compare A | B</source>
        <translation>Confronta A | B</translation>
    </message>
    <message>
        <source>Pick focus distance</source>
        <translation>Scegli distanza di messa a fuoco</translation>
    </message>
    <message>
        <source>Click a surface: the camera looked through focuses at its depth</source>
        <translation>Fai clic su una superficie: la camera attraverso cui guardi mette a fuoco alla sua profondità</translation>
    </message>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>La scelta del fuoco funziona attraverso una camera della scena: selezionane una e guarda attraverso (0).</translation>
    </message>
    <message>
        <source>Click the surface to focus on (Esc cancels).</source>
        <translation>Fai clic sulla superficie da mettere a fuoco (Esc annulla).</translation>
    </message>
    <message>
        <source>Pause viewport rendering</source>
        <translation>Metti in pausa il rendering della vista</translation>
    </message>
    <message>
        <source>Stop adding samples; edits are still shown at full resolution</source>
        <translation>Smette di aggiungere campioni; le modifiche sono comunque mostrate a piena risoluzione</translation>
    </message>
    <message>
        <source>Denoise still image</source>
        <translation>Riduci il rumore dell'immagine ferma</translation>
    </message>
    <message>
        <source>Filter the accumulated image while it converges (off: the raw running mean; renders are never filtered)</source>
        <translation>Filtra l'immagine accumulata mentre converge (spento: la media grezza; i render non sono mai filtrati)</translation>
    </message>
    <message>
        <source>coarse (1/%1 resolution)</source>
        <translation>grezza (risoluzione 1/%1)</translation>
    </message>
    <message>
        <source>refining to full resolution: %1%</source>
        <translation>affinamento a piena risoluzione: %1%</translation>
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
        <translation>%1 spp, convergita (limite di campioni della vista)</translation>
    </message>
    <message>
        <source>%1 spp, paused</source>
        <translation>%1 spp, in pausa</translation>
    </message>
    <message>
        <source>%1  |  %2 ms/frame</source>
        <translation>%1  |  %2 ms/fotogramma</translation>
    </message>
    <message>
        <source>Local axes</source>
        <translation>Assi locali</translation>
    </message>
    <message>
        <source>Move and rotate along the selected node's own axes (off: the world's)</source>
        <translation>Sposta e ruota lungo gli assi del nodo selezionato (spento: quelli del mondo)</translation>
    </message>
    <message>
        <source>up to %1 spp, converged (noise threshold)</source>
        <translation>fino a %1 spp, convergita (soglia di rumore)</translation>
    </message>
    <message>
        <source>%1, %2% converged</source>
        <translation>%1, %2% convergito</translation>
    </message>
</context>
</TS>