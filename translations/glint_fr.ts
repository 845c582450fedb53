<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="fr" sourcelanguage="en">
<context>
    <name>FocusPick</name>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>Le choix de la mise au point passe par une caméra de la scène : sélectionnez-en une et regardez à travers (0) d'abord.</translation>
    </message>
    <message>
        <source>Pick focus: %1 follows its camera path, whose keys set the focus; edit them in the timeline.</source>
        <translation>Choix de la mise au point : %1 suit son trajet, dont les clés fixent la mise au point ; modifiez-les dans la chronologie.</translation>
    </message>
    <message>
        <source>Pick focus: nothing under the cursor, the focus distance is unchanged.</source>
        <translation>Choix de la mise au point : rien sous le curseur, la distance reste inchangée.</translation>
    </message>
    <message>
        <source>Pick focus: the surface is behind the camera, the focus distance is unchanged.</source>
        <translation>Choix de la mise au point : la surface est derrière la caméra, la distance reste inchangée.</translation>
    </message>
    <message>
        <source>Focus distance of %1: %2 m (%3)</source>
        <translation>Distance de mise au point de %1 : %2 m (%3)</translation>
    </message>
</context>
<context>
    <name>OverlayPainter</name>
    <message>
        <source>BVH nodes + primitives</source>
        <translation>Nœuds BVH + primitives</translation>
    </message>
</context>
<context>
    <name>glint::editor</name>
    <message>
        <source>%1 cannot be read as an image: %2</source>
        <translation>%1 ne peut pas être lu comme une image : %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted: %2</source>
        <translation>%1 ne peut pas être converti : %2</translation>
    </message>
    <message>
        <source>%1 cannot be converted to PNG: %2</source>
        <translation>%1 ne peut pas être converti en PNG : %2</translation>
    </message>
    <message>
        <source>The material no longer exists.</source>
        <translation>Le matériau n'existe plus.</translation>
    </message>
    <message>
        <source>A material needs a name.</source>
        <translation>Un matériau a besoin d'un nom.</translation>
    </message>
    <message>
        <source>Delete unused materials</source>
        <translation>Supprimer les matériaux inutilisés</translation>
    </message>
    <message>
        <source>Select a shape or a mesh to assign the material to.</source>
        <translation>Sélectionnez une forme ou un maillage auquel affecter le matériau.</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Affecter le matériau</translation>
    </message>
    <message>
        <source>The mesh no longer exists.</source>
        <translation>Le maillage n'existe plus.</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 n'existe pas.</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 ne peut pas être lu : %2</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 est vide.</translation>
    </message>
    <message>
        <source>Load texture %1</source>
        <translation>Charger la texture %1</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Clé de transformation</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Coller la clé</translation>
    </message>
</context>
<context>
    <name>glint::editor::Autosave</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>Impossible de créer le dossier de sauvegarde automatique %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::ColorField</name>
    <message>
        <source>Choose a colour</source>
        <translation>Choisir une couleur</translation>
    </message>
    <message>
        <source>%1 (sRGB); stored linear: %2, %3, %4</source>
        <translation>%1 (sRGB) ; stocké en linéaire : %2, %3, %4</translation>
    </message>
</context>
<context>
    <name>glint::editor::CommandLabels</name>
    <message>
        <source>Rename</source>
        <translation>Renommer</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Déplacer</translation>
    </message>
    <message>
        <source>Show/hide</source>
        <translation>Afficher/masquer</translation>
    </message>
    <message>
        <source>Edit component</source>
        <translation>Modifier le composant</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Changer de parent</translation>
    </message>
    <message>
        <source>Edit settings</source>
        <translation>Modifier les paramètres</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Retirer</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Dupliquer</translation>
    </message>
    <message>
        <source>Add camera key</source>
        <translation>Ajouter une clé de caméra</translation>
    </message>
    <message>
        <source>Edit camera key</source>
        <translation>Modifier la clé de caméra</translation>
    </message>
    <message>
        <source>Move camera key</source>
        <translation>Déplacer la clé de caméra</translation>
    </message>
    <message>
        <source>Remove camera key</source>
        <translation>Retirer la clé de caméra</translation>
    </message>
    <message>
        <source>Camera path mode</source>
        <translation>Mode du trajet de caméra</translation>
    </message>
    <message>
        <source>mesh</source>
        <translation>maillage</translation>
    </message>
    <message>
        <source>material</source>
        <translation>matériau</translation>
    </message>
    <message>
        <source>texture</source>
        <translation>texture</translation>
    </message>
    <message>
        <source>image</source>
        <translation>image</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>échantillonneur</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Ajouter %1</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>Retirer %1</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>Dupliquer %1</translation>
    </message>
    <message>
        <source>Edit %1</source>
        <translation>Modifier %1</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Pivoter</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Mettre à l'échelle</translation>
    </message>
    <message>
        <source>Transform</source>
        <translation>Transformation</translation>
    </message>
    <message>
        <source>Change configuration</source>
        <translation>Modifier la configuration</translation>
    </message>
    <message>
        <source>Change image size</source>
        <translation>Modifier la taille de l'image</translation>
    </message>
    <message>
        <source>Change samples per pixel</source>
        <translation>Modifier les échantillons par pixel</translation>
    </message>
    <message>
        <source>Change bounces</source>
        <translation>Modifier les rebonds</translation>
    </message>
    <message>
        <source>Change seed</source>
        <translation>Modifier la graine</translation>
    </message>
    <message>
        <source>Change exposure</source>
        <translation>Modifier l'exposition</translation>
    </message>
    <message>
        <source>Change tonemapper</source>
        <translation>Modifier le tone mapping</translation>
    </message>
    <message>
        <source>Change radiance clamp</source>
        <translation>Modifier la limite de radiance</translation>
    </message>
    <message>
        <source>Change TAA settings</source>
        <translation>Modifier les réglages TAA</translation>
    </message>
    <message>
        <source>Change SVGF settings</source>
        <translation>Modifier les réglages SVGF</translation>
    </message>
    <message>
        <source>Change environment image</source>
        <translation>Modifier l'image d'environnement</translation>
    </message>
    <message>
        <source>Change environment colour</source>
        <translation>Modifier la couleur d'environnement</translation>
    </message>
    <message>
        <source>Change environment intensity</source>
        <translation>Modifier l'intensité d'environnement</translation>
    </message>
    <message>
        <source>Rotate environment</source>
        <translation>Tourner l'environnement</translation>
    </message>
    <message>
        <source>Change active camera</source>
        <translation>Modifier la caméra active</translation>
    </message>
    <message>
        <source>Change timeline range</source>
        <translation>Modifier la plage de la chronologie</translation>
    </message>
    <message>
        <source>Change frame rate</source>
        <translation>Modifier la cadence</translation>
    </message>
    <message>
        <source>Change output</source>
        <translation>Modifier la sortie</translation>
    </message>
    <message>
        <source>Change light units</source>
        <translation>Modifier les unités de lumière</translation>
    </message>
    <message>
        <source>Change light type</source>
        <translation>Modifier le type de lumière</translation>
    </message>
    <message>
        <source>Change light colour</source>
        <translation>Modifier la couleur de la lumière</translation>
    </message>
    <message>
        <source>Change light intensity</source>
        <translation>Modifier l'intensité de la lumière</translation>
    </message>
    <message>
        <source>Change light range</source>
        <translation>Modifier la portée de la lumière</translation>
    </message>
    <message>
        <source>Change light radius</source>
        <translation>Modifier le rayon de la lumière</translation>
    </message>
    <message>
        <source>Change spot cone</source>
        <translation>Modifier le cône du projecteur</translation>
    </message>
    <message>
        <source>Change sun size</source>
        <translation>Modifier la taille du soleil</translation>
    </message>
    <message>
        <source>Change projection</source>
        <translation>Modifier la projection</translation>
    </message>
    <message>
        <source>Change field of view</source>
        <translation>Modifier le champ de vision</translation>
    </message>
    <message>
        <source>Change aperture</source>
        <translation>Modifier l'ouverture</translation>
    </message>
    <message>
        <source>Change focus distance</source>
        <translation>Modifier la distance de mise au point</translation>
    </message>
    <message>
        <source>Change clipping</source>
        <translation>Modifier le découpage</translation>
    </message>
    <message>
        <source>Change aspect ratio</source>
        <translation>Modifier les proportions</translation>
    </message>
    <message>
        <source>Change shape</source>
        <translation>Modifier la forme</translation>
    </message>
    <message>
        <source>Change radius</source>
        <translation>Modifier le rayon</translation>
    </message>
    <message>
        <source>Change height</source>
        <translation>Modifier la hauteur</translation>
    </message>
    <message>
        <source>Change size</source>
        <translation>Modifier la taille</translation>
    </message>
    <message>
        <source>Change material</source>
        <translation>Modifier le matériau</translation>
    </message>
    <message>
        <source>Change base colour</source>
        <translation>Modifier la couleur de base</translation>
    </message>
    <message>
        <source>Change opacity</source>
        <translation>Modifier l'opacité</translation>
    </message>
    <message>
        <source>Change metallic</source>
        <translation>Modifier le métallique</translation>
    </message>
    <message>
        <source>Change roughness</source>
        <translation>Modifier la rugosité</translation>
    </message>
    <message>
        <source>Change emission</source>
        <translation>Modifier l'émission</translation>
    </message>
    <message>
        <source>Change emission strength</source>
        <translation>Modifier la force d'émission</translation>
    </message>
    <message>
        <source>Change specular</source>
        <translation>Modifier le spéculaire</translation>
    </message>
    <message>
        <source>Change transmission</source>
        <translation>Modifier la transmission</translation>
    </message>
    <message>
        <source>Change index of refraction</source>
        <translation>Modifier l'indice de réfraction</translation>
    </message>
    <message>
        <source>Change volume</source>
        <translation>Modifier le volume</translation>
    </message>
    <message>
        <source>Change alpha mode</source>
        <translation>Modifier le mode alpha</translation>
    </message>
    <message>
        <source>Change double sided</source>
        <translation>Modifier le double face</translation>
    </message>
    <message>
        <source>Change texture</source>
        <translation>Modifier la texture</translation>
    </message>
    <message>
        <source>Rename material</source>
        <translation>Renommer le matériau</translation>
    </message>
    <message>
        <source>Change bloom</source>
        <translation>Modifier le bloom</translation>
    </message>
    <message>
        <source>New material</source>
        <translation>Nouveau matériau</translation>
    </message>
    <message>
        <source>Duplicate material</source>
        <translation>Dupliquer le matériau</translation>
    </message>
    <message>
        <source>Assign material</source>
        <translation>Affecter le matériau</translation>
    </message>
    <message>
        <source>Change motion blur</source>
        <translation>Modifier le flou de mouvement</translation>
    </message>
    <message>
        <source>Change adaptive sampling</source>
        <translation>Modifier l'échantillonnage adaptatif</translation>
    </message>
    <message>
        <source>Change fog</source>
        <translation>Modifier le brouillard</translation>
    </message>
    <message>
        <source>Add studio environment</source>
        <translation>Ajouter l'environnement studio</translation>
    </message>
    <message>
        <source>Change sample blocks</source>
        <translation>Modifier les blocs d'échantillons</translation>
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
        <translation>La scène n'a pas encore de nom de fichier : utilisez Enregistrer sous.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
</context>
<context>
    <name>glint::editor::EditOperations</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>Rien n'est sélectionné.</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Dupliquer</translation>
    </message>
    <message>
        <source>The node no longer exists.</source>
        <translation>Le nœud n'existe plus.</translation>
    </message>
    <message>
        <source>A node cannot be moved into itself or its own children.</source>
        <translation>Un nœud ne peut pas être déplacé dans lui-même ni dans ses enfants.</translation>
    </message>
    <message>
        <source>Reparent</source>
        <translation>Changer de parent</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Ajouter %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::ExportDialog</name>
    <message>
        <source>Export image</source>
        <translation>Exporter une image</translation>
    </message>
    <message>
        <source>Export animation</source>
        <translation>Exporter une animation</translation>
    </message>
    <message>
        <source>Output file</source>
        <translation>Fichier de sortie</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Parcourir...</translation>
    </message>
    <message>
        <source>Images (*.exr *.png *.jpg *.tif)</source>
        <translation>Images (*.exr *.png *.jpg *.tif)</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Sortie</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Largeur</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Hauteur</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configuration</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Échantillons par pixel</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Graine</translation>
    </message>
    <message>
        <source>EXR layers</source>
        <translation>Calques EXR</translation>
    </message>
    <message>
        <source>all, none, or a list of albedo, normal, depth, id, variance</source>
        <translation>all, none, ou une liste parmi albedo, normal, depth, id, variance</translation>
    </message>
    <message>
        <source>Render passes</source>
        <translation>Passes de rendu</translation>
    </message>
    <message>
        <source>EXR only, Accumulate and Reference: none, all, light, or a list of DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</source>
        <translation>EXR seulement, Accumulate et Reference : none, all, light ou une liste de DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucune</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <source>First frame</source>
        <translation>Première image</translation>
    </message>
    <message>
        <source>Last frame</source>
        <translation>Dernière image</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Images</translation>
    </message>
    <message>
        <source>Video file</source>
        <translation>Fichier vidéo</translation>
    </message>
    <message>
        <source>optional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</source>
        <translation>facultatif : .mp4 (H.264), .mov (ProRes), .mkv (FFV1)</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Vidéo</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Rendering...</source>
        <translation>Rendu en cours...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryModel</name>
    <message>
        <source>&lt;empty&gt;</source>
        <translation>&lt;vide&gt;</translation>
    </message>
    <message>
        <source> (saved)</source>
        <translation> (enregistré)</translation>
    </message>
</context>
<context>
    <name>glint::editor::HistoryPanel</name>
    <message>
        <source>Undo history</source>
        <translation>Historique d'annulation</translation>
    </message>
</context>
<context>
    <name>glint::editor::KeyedTransform</name>
    <message>
        <source>Transform and key</source>
        <translation>Transformer et poser une clé</translation>
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
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop reading the file; the open scene stays as it is</source>
        <translation>Arrête la lecture du fichier ; la scène ouverte reste telle quelle</translation>
    </message>
    <message>
        <source>Loading progress</source>
        <translation>Progression du chargement</translation>
    </message>
</context>
<context>
    <name>glint::editor::LogPanel</name>
    <message>
        <source>Log messages</source>
        <translation>Messages du journal</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Effacer</translation>
    </message>
    <message>
        <source>Clear the log</source>
        <translation>Effacer le journal</translation>
    </message>
    <message>
        <source>info</source>
        <translation>info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>avertissement</translation>
    </message>
    <message>
        <source>error</source>
        <translation>erreur</translation>
    </message>
</context>
<context>
    <name>glint::editor::MainWindow</name>
    <message>
        <source>Glint scene editor</source>
        <translation>Éditeur de scènes Glint</translation>
    </message>
    <message>
        <source>Scene to open</source>
        <translation>Scène à ouvrir</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Échec de la sauvegarde automatique : %1</translation>
    </message>
    <message>
        <source>The viewport is not available in this build.</source>
        <translation>La vue n'est pas disponible dans cette version.</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vue</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Arborescence</translation>
    </message>
    <message>
        <source>Undo history</source>
        <translation>Historique d'annulation</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Journal</translation>
    </message>
    <message>
        <source>Nothing selected</source>
        <translation>Aucune sélection</translation>
    </message>
    <message>
        <source>Selected: %1</source>
        <translation>Sélection : %1</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes selected</source>
        <translation><numerusform>%n nœud sélectionné</numerusform><numerusform>%n nœuds sélectionnés</numerusform></translation>
    </message>
    <message>
        <source>Selection</source>
        <translation>Sélection</translation>
    </message>
    <message>
        <source>Scene statistics</source>
        <translation>Statistiques de la scène</translation>
    </message>
    <message>
        <source>Render progress</source>
        <translation>Progression du rendu</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>"%1" has unsaved changes. Save them first?</source>
        <translation>« %1 » a des modifications non enregistrées. Les enregistrer d'abord ?</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>Impossible d'ouvrir %1 : %2</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Ouvrir</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 ouvert</translation>
    </message>
    <message>
        <source>Cannot import %1: %2</source>
        <translation>Impossible d'importer %1 : %2</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>%1 importé</translation>
    </message>
    <message>
        <source>Cannot save: %1</source>
        <translation>Impossible d'enregistrer : %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Enregistrer la scène</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb)</source>
        <translation>Scènes glTF (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>Impossible d'enregistrer %1 : %2</translation>
    </message>
    <message>
        <source>an untitled scene</source>
        <translation>une scène sans titre</translation>
    </message>
    <message>
        <source>Cannot recover the autosaved copy: %1</source>
        <translation>Impossible de récupérer la copie enregistrée automatiquement : %1</translation>
    </message>
    <message>
        <source>Recovered the autosaved copy of %1</source>
        <translation>Copie enregistrée automatiquement de %1 récupérée</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Ouvrir...</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Ouvrir une scène</translation>
    </message>
    <message>
        <source>Scenes (*.gltf *.glb *.glint.json);;All files (*)</source>
        <translation>Scènes (*.gltf *.glb *.glint.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importer...</translation>
    </message>
    <message>
        <source>Import into the scene</source>
        <translation>Importer dans la scène</translation>
    </message>
    <message>
        <source>Scenes and models (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;All files (*)</source>
        <translation>Scènes et modèles (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Enregistrer &amp;sous...</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Préférences...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>D&amp;upliquer</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>&amp;Tout sélectionner</translation>
    </message>
    <message>
        <source>Select &amp;None</source>
        <translation>&amp;Ne rien sélectionner</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Panneaux</translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation>&amp;Thème</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Système</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Sombre</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>&amp;About Glint</source>
        <translation>À &amp;propos de Glint</translation>
    </message>
    <message>
        <source>About Glint</source>
        <translation>À propos de Glint</translation>
    </message>
    <message>
        <source>Glint %1: a scene editor with a built-in OpenGL 4.1 path tracer.</source>
        <translation>Glint %1 : un éditeur de scènes avec un path tracer OpenGL 4.1 intégré.</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>À propos de &amp;Qt</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Barre d'outils principale</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Affichage</translation>
    </message>
    <message>
        <source>View toolbar</source>
        <translation>Barre d'outils de la vue</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Vider la liste</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annuler %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rétablir %1</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Chronologie</translation>
    </message>
    <message>
        <source>Export &amp;Image...</source>
        <translation>Exporter une &amp;image...</translation>
    </message>
    <message>
        <source>Export A&amp;nimation...</source>
        <translation>Exporter une a&amp;nimation...</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Ouverture de %1</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importation de %1</translation>
    </message>
    <message>
        <source>Recovering an untitled scene</source>
        <translation>Récupération d'une scène sans titre</translation>
    </message>
    <message>
        <source>Recovering %1</source>
        <translation>Récupération de %1</translation>
    </message>
    <message>
        <source>Cannot open %1:
%2</source>
        <translation>Impossible d'ouvrir %1 :
%2</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Importation de %1 annulée</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>Ouverture de %1 annulée</translation>
    </message>
    <message>
        <source>This display gives no OpenGL 4.1 core context, so the editor opens without its viewport; `glint render` renders headless (EGL).</source>
        <translation>Cet affichage ne fournit pas de contexte OpenGL 4.1 core : l'éditeur s'ouvre donc sans sa vue ; `glint render` effectue le rendu sans affichage (EGL).</translation>
    </message>
    <message>
        <source>%1, %2, configuration: %3</source>
        <translation>%1, %2, configuration : %3</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes</source>
        <translation><numerusform>%n nœud</numerusform><numerusform>%n nœuds</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n triangles</source>
        <translation><numerusform>%n triangle</numerusform><numerusform>%n triangles</numerusform></translation>
    </message>
    <message>
        <source>%1 (autosaved %2)</source>
        <translation>%1 (enregistré automatiquement %2)</translation>
    </message>
    <message>
        <source>Discard all autosaved copies</source>
        <translation>Supprimer toutes les copies enregistrées automatiquement</translation>
    </message>
    <message>
        <source>Nothing to recover</source>
        <translation>Rien à récupérer</translation>
    </message>
    <message>
        <source>Glint did not close normally: the copy of %1 autosaved at %2 is newer than the file.</source>
        <translation>Glint ne s'est pas fermé normalement : la copie de %1 enregistrée automatiquement à %2 est plus récente que le fichier.</translation>
    </message>
    <message>
        <source>Glint did not close normally: unsaved work on %1 was autosaved at %2.</source>
        <translation>Glint ne s'est pas fermé normalement : le travail non enregistré sur %1 a été enregistré automatiquement à %2.</translation>
    </message>
    <message numerus="yes">
        <source>%n more in File &gt; Recover.</source>
        <translation><numerusform>%n autre dans Fichier &gt; Récupérer.</numerusform><numerusform>%n autres dans Fichier &gt; Récupérer.</numerusform></translation>
    </message>
    <message>
        <source>Re&amp;cover</source>
        <translation>Ré&amp;cupérer</translation>
    </message>
    <message>
        <source>There are no meshes in %1: nothing to import.</source>
        <translation>%1 ne contient aucun maillage : rien à importer.</translation>
    </message>
    <message>
        <source>%1 holds a mesh without any faces, so it cannot be imported.</source>
        <translation>%1 contient un maillage sans aucune face : il ne peut pas être importé.</translation>
    </message>
    <message>
        <source>%1 is in no format Glint imports (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</source>
        <translation>%1 n'est dans aucun format que Glint importe (glTF, OBJ, PLY, STL, FBX, DAE, 3DS).</translation>
    </message>
    <message>
        <source>%1 ends too early: the file is damaged or was not copied completely.</source>
        <translation>%1 se termine trop tôt : le fichier est endommagé ou n'a pas été copié entièrement.</translation>
    </message>
    <message>
        <source>%1 cannot be read.</source>
        <translation>%1 ne peut pas être lu.</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 est vide.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importer</translation>
    </message>
    <message>
        <source>Cannot import %1:
%2</source>
        <translation>Impossible d'importer %1 :
%2</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Matériaux</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Nouvelle scène</translation>
    </message>
    <message>
        <source>New from &amp;template</source>
        <translation>Nouveau depuis un &amp;modèle</translation>
    </message>
    <message>
        <source>%1 (autosaved %2, older than the file)</source>
        <translation>%1 (enregistré automatiquement %2, plus ancien que le fichier)</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialListModel</name>
    <message>
        <source>Material %1</source>
        <translation>Matériau %1</translation>
    </message>
    <message>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message numerus="yes">
        <source>%n users</source>
        <translation><numerusform>%n utilisateur</numerusform><numerusform>%n utilisateurs</numerusform></translation>
    </message>
    <message>
        <source>%1: no node uses it (Delete unused removes it)</source>
        <translation>%1 : aucun nœud ne l'utilise (Supprimer les inutilisés le retire)</translation>
    </message>
    <message>
        <source>%1: drag it onto a node in the outliner or the viewport to assign it</source>
        <translation>%1 : faites-le glisser sur un nœud de l'arborescence ou de la vue pour l'affecter</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialPresets</name>
    <message>
        <source>Plastic</source>
        <translation>Plastique</translation>
    </message>
    <message>
        <source>Rough</source>
        <translation>Rugueux</translation>
    </message>
    <message>
        <source>Glossy (clear coat)</source>
        <translation>Brillant (vernis)</translation>
    </message>
    <message>
        <source>Metal</source>
        <translation>Métal</translation>
    </message>
    <message>
        <source>Gold</source>
        <translation>Or</translation>
    </message>
    <message>
        <source>Brushed metal</source>
        <translation>Métal brossé</translation>
    </message>
    <message>
        <source>Glass</source>
        <translation>Verre</translation>
    </message>
    <message>
        <source>Frosted glass</source>
        <translation>Verre dépoli</translation>
    </message>
    <message>
        <source>Emitter</source>
        <translation>Émetteur</translation>
    </message>
</context>
<context>
    <name>glint::editor::MaterialsPanel</name>
    <message>
        <source>Search materials</source>
        <translation>Rechercher des matériaux</translation>
    </message>
    <message>
        <source>Material search</source>
        <translation>Recherche de matériaux</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Matériaux</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nouveau</translation>
    </message>
    <message>
        <source>A new material from a preset</source>
        <translation>Un nouveau matériau à partir d'un préréglage</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Dupliquer</translation>
    </message>
    <message>
        <source>A copy of the selected material</source>
        <translation>Une copie du matériau sélectionné</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renommer</translation>
    </message>
    <message>
        <source>Rename the selected material</source>
        <translation>Renommer le matériau sélectionné</translation>
    </message>
    <message>
        <source>Delete unused</source>
        <translation>Supprimer les inutilisés</translation>
    </message>
    <message>
        <source>Remove every material no node uses</source>
        <translation>Supprime chaque matériau qu'aucun nœud n'utilise</translation>
    </message>
    <message>
        <source>Assign to selection</source>
        <translation>Affecter à la sélection</translation>
    </message>
    <message>
        <source>Give the selected material to every selected shape and mesh (one undo step)</source>
        <translation>Affecte le matériau sélectionné à chaque forme et maillage sélectionnés (une seule étape d'annulation)</translation>
    </message>
    <message numerus="yes">
        <source>%n unused materials removed.</source>
        <translation><numerusform>%n matériau inutilisé supprimé.</numerusform><numerusform>%n matériaux inutilisés supprimés.</numerusform></translation>
    </message>
    <message>
        <source>Select a material in the list first.</source>
        <translation>Sélectionnez d'abord un matériau dans la liste.</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeKeyTracks</name>
    <message>
        <source>Node keys</source>
        <translation>Clés des nœuds</translation>
    </message>
</context>
<context>
    <name>glint::editor::NodeNames</name>
    <message>
        <source>Sphere %1</source>
        <translation>Sphère %1</translation>
    </message>
    <message>
        <source>Quad %1</source>
        <translation>Quad %1</translation>
    </message>
    <message>
        <source>Disk %1</source>
        <translation>Disque %1</translation>
    </message>
    <message>
        <source>Box %1</source>
        <translation>Boîte %1</translation>
    </message>
    <message>
        <source>Cylinder %1</source>
        <translation>Cylindre %1</translation>
    </message>
    <message>
        <source>Ground plane %1</source>
        <translation>Plan du sol %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Nœud %1</translation>
    </message>
    <message>
        <source>Sun %1</source>
        <translation>Soleil %1</translation>
    </message>
    <message>
        <source>Point light %1</source>
        <translation>Lumière ponctuelle %1</translation>
    </message>
    <message>
        <source>Spot light %1</source>
        <translation>Projecteur %1</translation>
    </message>
    <message>
        <source>Mesh %1</source>
        <translation>Maillage %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Caméra %1</translation>
    </message>
    <message>
        <source>Area light %1</source>
        <translation>Lumière surfacique %1</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerModel</name>
    <message>
        <source>Mesh</source>
        <translation>Maillage</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forme</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Groupe</translation>
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
        <translation>Masqué</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>%1 (%2; the file gives it no name)</source>
        <translation>%1 (%2 ; le fichier ne lui donne pas de nom)</translation>
    </message>
</context>
<context>
    <name>glint::editor::OutlinerPanel</name>
    <message>
        <source>Filter by name</source>
        <translation>Filtrer par nom</translation>
    </message>
    <message>
        <source>Outliner filter</source>
        <translation>Filtre de l'arborescence</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Add a shape, light or camera</source>
        <translation>Ajouter une forme, une lumière ou une caméra</translation>
    </message>
    <message>
        <source>Scene outliner</source>
        <translation>Arborescence de la scène</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forme</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Sphère</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Boîte</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Quadrilatère</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Disque</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Cylindre</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Plan du sol</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Point light</source>
        <translation>Lumière ponctuelle</translation>
    </message>
    <message>
        <source>Spot light</source>
        <translation>Projecteur</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Soleil</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>Empty group</source>
        <translation>Groupe vide</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renommer</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Dupliquer</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Area rectangle</source>
        <translation>Rectangle surfacique</translation>
    </message>
    <message>
        <source>Area disk</source>
        <translation>Disque surfacique</translation>
    </message>
    <message>
        <source>Area sphere</source>
        <translation>Sphère surfacique</translation>
    </message>
    <message>
        <source>Portal pair</source>
        <translation>Paire de portails</translation>
    </message>
    <message>
        <source>Studio environment</source>
        <translation>Environnement studio</translation>
    </message>
</context>
<context>
    <name>glint::editor::PortalEdits</name>
    <message>
        <source>Add Portal Pair</source>
        <translation>Ajouter une paire de portails</translation>
    </message>
    <message>
        <source>Portal A</source>
        <translation>Portail A</translation>
    </message>
    <message>
        <source>Portal B</source>
        <translation>Portail B</translation>
    </message>
    <message>
        <source>Only a quad can be a portal.</source>
        <translation>Seul un quadrilatère peut être un portail.</translation>
    </message>
    <message>
        <source>A portal cannot lead to itself.</source>
        <translation>Un portail ne peut pas mener à lui-même.</translation>
    </message>
    <message>
        <source>A portal can only lead to another quad.</source>
        <translation>Un portail ne peut mener qu'à un autre quadrilatère.</translation>
    </message>
    <message>
        <source>Link Portals</source>
        <translation>Relier les portails</translation>
    </message>
    <message>
        <source>Unlink Portal</source>
        <translation>Délier le portail</translation>
    </message>
</context>
<context>
    <name>glint::editor::Preferences</name>
    <message>
        <source>System language</source>
        <translation>Langue du système</translation>
    </message>
</context>
<context>
    <name>glint::editor::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Préférences</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Général</translation>
    </message>
    <message>
        <source>Keymap</source>
        <translation>Raccourcis</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Système</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Sombre</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Thème</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Désactivé</translation>
    </message>
    <message>
        <source>Autosave interval</source>
        <translation>Intervalle de sauvegarde automatique</translation>
    </message>
    <message>
        <source>Autosave every</source>
        <translation>Sauvegarde automatique toutes les</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Commande</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Raccourci</translation>
    </message>
    <message>
        <source>Shortcut for %1</source>
        <translation>Raccourci pour %1</translation>
    </message>
    <message>
        <source>Shortcut conflict</source>
        <translation>Conflit de raccourcis</translation>
    </message>
    <message>
        <source>%1 is used by both "%2" and "%3".</source>
        <translation>%1 est utilisé par « %2 » et « %3 ».</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Aucune limite</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Échantillons de la vue</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here (renders use the Scene panel's samples)</source>
        <translation>La vue cesse d'ajouter des échantillons par pixel ici (les rendus utilisent les échantillons du panneau Scène)</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Par défaut</translation>
    </message>
    <message>
        <source>Reset all to defaults</source>
        <translation>Tout réinitialiser par défaut</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertiesPanel</name>
    <message>
        <source>Scene settings</source>
        <translation>Paramètres de la scène</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Select a node in the outliner or the viewport to edit it.</source>
        <translation>Sélectionnez un nœud dans l'arborescence ou la vue pour le modifier.</translation>
    </message>
</context>
<context>
    <name>glint::editor::PropertyEdits</name>
    <message>
        <source>Edit %1 nodes</source>
        <translation>Modifier %1 nœuds</translation>
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
        <translation>Miniature de %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(aucune)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>sans nom</translation>
    </message>
    <message>
        <source>Material: %1</source>
        <translation>Matériau : %1</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>Couleur de base</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Opacité</translation>
    </message>
    <message>
        <source>Base colour texture</source>
        <translation>Texture de couleur de base</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Métallique</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rugosité</translation>
    </message>
    <message>
        <source>Metallic-roughness texture</source>
        <translation>Texture métallique-rugosité</translation>
    </message>
    <message>
        <source>Normal texture</source>
        <translation>Texture de normales</translation>
    </message>
    <message>
        <source>Occlusion texture</source>
        <translation>Texture d'occlusion</translation>
    </message>
    <message>
        <source>Emission</source>
        <translation>Émission</translation>
    </message>
    <message>
        <source>Emission strength</source>
        <translation>Intensité d'émission</translation>
    </message>
    <message>
        <source>Emission texture</source>
        <translation>Texture d'émission</translation>
    </message>
    <message>
        <source>Specular</source>
        <translation>Spéculaire</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>Couleur spéculaire</translation>
    </message>
    <message>
        <source>Specular texture</source>
        <translation>Texture spéculaire</translation>
    </message>
    <message>
        <source>Specular colour texture</source>
        <translation>Texture de couleur spéculaire</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>Transmission</translation>
    </message>
    <message>
        <source>Transmission texture</source>
        <translation>Texture de transmission</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>Indice de réfraction</translation>
    </message>
    <message>
        <source>Thickness</source>
        <translation>Épaisseur</translation>
    </message>
    <message>
        <source>Thickness texture</source>
        <translation>Texture d'épaisseur</translation>
    </message>
    <message>
        <source>Attenuation distance (m)</source>
        <translation>Distance d'atténuation (m)</translation>
    </message>
    <message>
        <source>Attenuation colour</source>
        <translation>Couleur d'atténuation</translation>
    </message>
    <message>
        <source>Alpha mode</source>
        <translation>Mode alpha</translation>
    </message>
    <message>
        <source>Opaque</source>
        <translation>Opaque</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Masque</translation>
    </message>
    <message>
        <source>Blend</source>
        <translation>Mélange</translation>
    </message>
    <message>
        <source>Alpha cutoff</source>
        <translation>Seuil alpha</translation>
    </message>
    <message>
        <source>Double sided</source>
        <translation>Double face</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Nœud</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Visible</translation>
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
        <translation>Rotation %1 (degrés)</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <translation>Échelle %1</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forme</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Sphère</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>Quadrilatère</translation>
    </message>
    <message>
        <source>Disk</source>
        <translation>Disque</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Boîte</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Cylindre</translation>
    </message>
    <message>
        <source>Ground plane</source>
        <translation>Plan du sol</translation>
    </message>
    <message>
        <source>Radius (m)</source>
        <translation>Rayon (m)</translation>
    </message>
    <message>
        <source>Height (m)</source>
        <translation>Hauteur (m)</translation>
    </message>
    <message>
        <source>Size %1 (m)</source>
        <translation>Taille %1 (m)</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Soleil</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Ponctuelle</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Projecteur</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Couleur</translation>
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
        <translation>unités Blender</translation>
    </message>
    <message>
        <source>raw units</source>
        <translation>unités brutes</translation>
    </message>
    <message>
        <source>Intensity (%1, %2)</source>
        <translation>Intensité (%1, %2)</translation>
    </message>
    <message>
        <source>Range (m, 0 = infinite)</source>
        <translation>Portée (m, 0 = infinie)</translation>
    </message>
    <message>
        <source>Inner cone (degrees)</source>
        <translation>Cône intérieur (degrés)</translation>
    </message>
    <message>
        <source>Outer cone (degrees)</source>
        <translation>Cône extérieur (degrés)</translation>
    </message>
    <message>
        <source>Sun angular diameter (degrees)</source>
        <translation>Diamètre angulaire du soleil (degrés)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>Projection</source>
        <translation>Projection</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspective</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <translation>Orthographique</translation>
    </message>
    <message>
        <source>Vertical field of view (degrees)</source>
        <translation>Champ de vision vertical (degrés)</translation>
    </message>
    <message>
        <source>Lens radius (m)</source>
        <translation>Rayon de l'objectif (m)</translation>
    </message>
    <message>
        <source>Focus distance (m)</source>
        <translation>Distance de mise au point (m)</translation>
    </message>
    <message>
        <source>Exposure (EV)</source>
        <translation>Exposition (IL)</translation>
    </message>
    <message>
        <source>Near clip (m)</source>
        <translation>Plan de découpe proche (m)</translation>
    </message>
    <message>
        <source>Active camera</source>
        <translation>Caméra active</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Environnement</translation>
    </message>
    <message>
        <source>HDR file</source>
        <translation>Fichier HDR</translation>
    </message>
    <message>
        <source>Colour (no file)</source>
        <translation>Couleur (sans fichier)</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensité</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>Rotation (degrés)</translation>
    </message>
    <message>
        <source>Render settings</source>
        <translation>Paramètres de rendu</translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configuration</translation>
    </message>
    <message>
        <source>Width (px)</source>
        <translation>Largeur (px)</translation>
    </message>
    <message>
        <source>Height (px)</source>
        <translation>Hauteur (px)</translation>
    </message>
    <message>
        <source>Samples per pixel</source>
        <translation>Échantillons par pixel</translation>
    </message>
    <message>
        <source>Bounces</source>
        <translation>Rebonds</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Graine</translation>
    </message>
    <message>
        <source>Tonemapper</source>
        <translation>Mappage des tons</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Aucun</translation>
    </message>
    <message>
        <source>ACES (fitted)</source>
        <translation>ACES (approché)</translation>
    </message>
    <message>
        <source>Khronos PBR Neutral</source>
        <translation>Khronos PBR Neutral</translation>
    </message>
    <message>
        <source>Radiance clamp (0 = off)</source>
        <translation>Limite de luminance (0 = désactivée)</translation>
    </message>
    <message>
        <source>Light units</source>
        <translation>Unités de lumière</translation>
    </message>
    <message>
        <source>Blender (W = lm / 683)</source>
        <translation>Blender (W = lm / 683)</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Brutes</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Parcourir...</translation>
    </message>
    <message>
        <source>Choose an HDR environment file</source>
        <translation>Choisir un fichier d'environnement HDR</translation>
    </message>
    <message>
        <source>Environment map</source>
        <translation>Carte d'environnement</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>Images HDR (*.hdr *.exr);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Camera and timeline</source>
        <translation>Caméra et chronologie</translation>
    </message>
    <message>
        <source>(the first camera)</source>
        <translation>(la première caméra)</translation>
    </message>
    <message>
        <source>Timeline start (s)</source>
        <translation>Début de la chronologie (s)</translation>
    </message>
    <message>
        <source>Timeline end (s, 0 = the animation's)</source>
        <translation>Fin de la chronologie (s, 0 = celle de l'animation)</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Images par seconde</translation>
    </message>
    <message>
        <source>Frames per second must be a positive number or a ratio such as 24000/1001, not "%1".</source>
        <translation>Les images par seconde doivent être un nombre positif ou un rapport comme 24000/1001, pas « %1 ».</translation>
    </message>
    <message>
        <source>Real-time reconstruction</source>
        <translation>Reconstruction en temps réel</translation>
    </message>
    <message>
        <source>TAA blend (current frame)</source>
        <translation>Mélange TAA (image actuelle)</translation>
    </message>
    <message>
        <source>TAA clip box (std. deviations)</source>
        <translation>Boîte d'écrêtage TAA (écarts-types)</translation>
    </message>
    <message>
        <source>TAA perceptual blend</source>
        <translation>Mélange perceptuel TAA</translation>
    </message>
    <message>
        <source>SVGF a-trous iterations</source>
        <translation>Itérations à trous SVGF</translation>
    </message>
    <message>
        <source>SVGF temporal alpha</source>
        <translation>Alpha temporel SVGF</translation>
    </message>
    <message>
        <source>SVGF moments alpha</source>
        <translation>Alpha des moments SVGF</translation>
    </message>
    <message>
        <source>SVGF luminance sigma</source>
        <translation>Sigma de luminance SVGF</translation>
    </message>
    <message>
        <source>SVGF normal sigma (exponent)</source>
        <translation>Sigma des normales SVGF (exposant)</translation>
    </message>
    <message>
        <source>SVGF depth sigma</source>
        <translation>Sigma de profondeur SVGF</translation>
    </message>
    <message>
        <source>SVGF firefly ratio</source>
        <translation>Rapport de lucioles SVGF</translation>
    </message>
    <message>
        <source>TAA history clipping</source>
        <translation>Écrêtage de l'historique TAA</translation>
    </message>
    <message>
        <source>Variance clip (YCoCg)</source>
        <translation>Écrêtage par variance (YCoCg)</translation>
    </message>
    <message>
        <source>Min/max clamp</source>
        <translation>Bornage min/max</translation>
    </message>
    <message>
        <source>None (ghosts)</source>
        <translation>Aucun (fantômes)</translation>
    </message>
    <message>
        <source>"%1" is relative, but the scene has no folder yet: choose the file with Browse, or save the scene first.</source>
        <translation>« %1 » est relatif, mais la scène n'a pas encore de dossier : choisissez le fichier avec Parcourir, ou enregistrez d'abord la scène.</translation>
    </message>
    <message>
        <source>Cannot read the environment image %1. Choose it again with Browse, or clear the field to use the colour below.</source>
        <translation>Impossible de lire l'image d'environnement %1. Choisissez-la de nouveau avec Parcourir, ou videz le champ pour utiliser la couleur ci-dessous.</translation>
    </message>
    <message>
        <source>Environment image status</source>
        <translation>État de l'image d'environnement</translation>
    </message>
    <message>
        <source>An infinite plane: the node's y = 0, facing +Y; move and turn it with the transform. It has no size. In the glTF file other programs (Blender) get a 200 m square in its place.</source>
        <translation>Un plan infini : y = 0 du nœud, orienté vers +Y ; déplacez-le et tournez-le avec la transformation. Il n'a pas de taille. Dans le fichier glTF, les autres programmes (Blender) reçoivent à sa place un carré de 200 m.</translation>
    </message>
    <message>
        <source>Half height (m)</source>
        <translation>Demi-hauteur (m)</translation>
    </message>
    <message>
        <source>AgX</source>
        <translation>AgX</translation>
    </message>
    <message>
        <source>Reinhard (extended)</source>
        <translation>Reinhard (étendu)</translation>
    </message>
    <message>
        <source>Hable (Uncharted 2)</source>
        <translation>Hable (Uncharted 2)</translation>
    </message>
    <message>
        <source>Bloom strength (0 = off)</source>
        <translation>Intensité du bloom (0 = désactivé)</translation>
    </message>
    <message>
        <source>Bloom radius (of the height)</source>
        <translation>Rayon du bloom (par rapport à la hauteur)</translation>
    </message>
    <message>
        <source>Edit sampler</source>
        <translation>Modifier l'échantillonneur</translation>
    </message>
    <message>
        <source>Load texture</source>
        <translation>Charger une texture</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</source>
        <translation>Images (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Charger…</translation>
    </message>
    <message>
        <source>Load an image file (PNG, JPEG, EXR, HDR, TIFF) into this slot</source>
        <translation>Charger un fichier image (PNG, JPEG, EXR, HDR, TIFF) dans cet emplacement</translation>
    </message>
    <message>
        <source>Load %1</source>
        <translation>Charger %1</translation>
    </message>
    <message>
        <source>UV set</source>
        <translation>Jeu d'UV</translation>
    </message>
    <message>
        <source>Repeat</source>
        <translation>Répéter</translation>
    </message>
    <message>
        <source>Clamp to edge</source>
        <translation>Bloquer au bord</translation>
    </message>
    <message>
        <source>Mirrored repeat</source>
        <translation>Répétition en miroir</translation>
    </message>
    <message>
        <source>Wrap U</source>
        <translation>Répétition U</translation>
    </message>
    <message>
        <source>Wrap V</source>
        <translation>Répétition V</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filtre</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <source>Nearest</source>
        <translation>Plus proche</translation>
    </message>
    <message>
        <source>Offset U</source>
        <translation>Décalage U</translation>
    </message>
    <message>
        <source>Offset V</source>
        <translation>Décalage V</translation>
    </message>
    <message>
        <source>Scale U</source>
        <translation>Échelle U</translation>
    </message>
    <message>
        <source>Scale V</source>
        <translation>Échelle V</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Matériaux</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Modifier</translation>
    </message>
    <message>
        <source>Show this primitive's material below</source>
        <translation>Afficher le matériau de cette primitive ci-dessous</translation>
    </message>
    <message numerus="yes">
        <source>Primitive %1 (%n triangles)</source>
        <translation><numerusform>Primitive %1 (%n triangle)</numerusform><numerusform>Primitive %1 (%n triangles)</numerusform></translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Matériau</translation>
    </message>
    <message>
        <source>(default)</source>
        <translation>(par défaut)</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>Matériau %1</translation>
    </message>
    <message>
        <source>Motion blur shutter (frames, 0 = off)</source>
        <translation>Obturateur du flou de mouvement (images, 0 = désactivé)</translation>
    </message>
    <message>
        <source>Rectangle</source>
        <translation>Rectangle</translation>
    </message>
    <message>
        <source>Power (W)</source>
        <translation>Puissance (W)</translation>
    </message>
    <message>
        <source>Size X (m)</source>
        <translation>Taille X (m)</translation>
    </message>
    <message>
        <source>Size Y (m)</source>
        <translation>Taille Y (m)</translation>
    </message>
    <message>
        <source>Diameter (m)</source>
        <translation>Diamètre (m)</translation>
    </message>
    <message>
        <source>Emits its power evenly from the front face (the light's -Z) of the rectangle or disk, or the outside of the sphere; in the glTF file other programs get an emissive mesh.</source>
        <translation>Émet sa puissance uniformément depuis la face avant (le -Z de la lumière) du rectangle ou du disque, ou depuis l'extérieur de la sphère ; dans le fichier glTF, les autres programmes reçoivent un maillage émissif.</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Surfacique</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vue</translation>
    </message>
    <message>
        <source>Viewport samples</source>
        <translation>Échantillons de la vue</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Aucune limite</translation>
    </message>
    <message>
        <source>The viewport stops adding samples per pixel here; renders use the samples per pixel above</source>
        <translation>La vue cesse d'ajouter des échantillons par pixel ici ; les rendus utilisent les échantillons par pixel ci-dessus</translation>
    </message>
    <message>
        <source>Rendering</source>
        <translation>Rendu</translation>
    </message>
    <message>
        <source>Noise threshold (adaptive sampling, 0 = off)</source>
        <translation>Seuil de bruit (échantillonnage adaptatif, 0 = désactivé)</translation>
    </message>
    <message>
        <source>Adaptive minimum samples (0 = automatic)</source>
        <translation>Échantillons minimaux adaptatifs (0 = automatique)</translation>
    </message>
    <message>
        <source>Scatter anisotropy</source>
        <translation>Anisotropie de diffusion</translation>
    </message>
    <message>
        <source>Scatter colour</source>
        <translation>Couleur de diffusion</translation>
    </message>
    <message>
        <source>Fog</source>
        <translation>Brouillard</translation>
    </message>
    <message>
        <source>Density (1/m)</source>
        <translation>Densité (1/m)</translation>
    </message>
    <message>
        <source>Anisotropy</source>
        <translation>Anisotropie</translation>
    </message>
    <message>
        <source>Height falloff (1/m)</source>
        <translation>Décroissance avec la hauteur (1/m)</translation>
    </message>
    <message>
        <source>Base height (m)</source>
        <translation>Hauteur de base (m)</translation>
    </message>
    <message>
        <source>node %1, deleted</source>
        <translation>nœud %1, supprimé</translation>
    </message>
    <message>
        <source>Not paired: the other side does not lead back here, so this quad is an ordinary surface. Choose a quad to pair them again.</source>
        <translation>Non appairé : l'autre côté ne ramène pas ici, ce quadrilatère est donc une surface ordinaire. Choisissez un quadrilatère pour les appairer de nouveau.</translation>
    </message>
    <message>
        <source>What enters this quad leaves the quad chosen here, and the other way round.</source>
        <translation>Ce qui entre dans ce quadrilatère sort du quadrilatère choisi ici, et inversement.</translation>
    </message>
    <message>
        <source>Portal to</source>
        <translation>Portail vers</translation>
    </message>
    <message>
        <source>Adaptive goal</source>
        <translation>Objectif adaptatif</translation>
    </message>
    <message>
        <source>Even noise (as Cycles)</source>
        <translation>Bruit uniforme (comme Cycles)</translation>
    </message>
    <message>
        <source>Least mean error</source>
        <translation>Erreur moyenne minimale</translation>
    </message>
    <message>
        <source>Sample blocks (pixels sharing a sequence)</source>
        <translation>Blocs d'échantillons (pixels partageant une séquence)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Désactivé</translation>
    </message>
</context>
<context>
    <name>glint::editor::RecoveryBar</name>
    <message>
        <source>Recover unsaved work</source>
        <translation>Récupérer le travail non enregistré</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Récupérer</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Delete the autosaved copy</source>
        <translation>Supprimer la copie enregistrée automatiquement</translation>
    </message>
    <message>
        <source>Later (File &gt; Recover keeps it)</source>
        <translation>Plus tard (reste dans Fichier &gt; Récupérer)</translation>
    </message>
    <message>
        <source>Hide</source>
        <translation>Masquer</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderHost</name>
    <message>
        <source>Preparing the scene</source>
        <translation>Préparation de la scène</translation>
    </message>
    <message>
        <source>building mesh BVHs</source>
        <translation>construction des BVH des maillages</translation>
    </message>
    <message>
        <source>decoding textures</source>
        <translation>décodage des textures</translation>
    </message>
    <message>
        <source>loading the environment</source>
        <translation>chargement de l'environnement</translation>
    </message>
    <message>
        <source>packing the scene</source>
        <translation>empaquetage de la scène</translation>
    </message>
    <message>
        <source>building the click picker</source>
        <translation>construction du sélecteur de clic</translation>
    </message>
    <message>
        <source>Preparing the scene: %1 %2/%3</source>
        <translation>Préparation de la scène : %1 %2/%3</translation>
    </message>
    <message>
        <source>Preparing the scene: %1</source>
        <translation>Préparation de la scène : %1</translation>
    </message>
    <message>
        <source>Nothing in the scene emits light, so the path-traced image is black: add a light (Add &gt; Light &gt; Studio environment lights any model) or an emissive material, or give the environment a colour or an image (Scene tab).</source>
        <translation>Rien dans la scène n'émet de lumière, l'image en path tracing est donc noire : ajoutez une lumière (Ajouter &gt; Lumière &gt; Environnement studio éclaire n'importe quel modèle) ou un matériau émissif, ou donnez à l'environnement une couleur ou une image (onglet Scène).</translation>
    </message>
    <message>
        <source>Only emissive textures give light in this scene, so most of the path-traced image is dark: add a light (Add &gt; Light &gt; Studio environment lights any model), or give the environment a colour or an image (Scene tab).</source>
        <translation>Dans cette scène, seules des textures émissives donnent de la lumière : l'image en path tracing est donc presque entièrement sombre. Ajoutez une lumière (Ajouter &gt; Lumière &gt; Environnement studio éclaire n'importe quel modèle), ou donnez à l'environnement une couleur ou une image (onglet Scène).</translation>
    </message>
</context>
<context>
    <name>glint::editor::RenderView</name>
    <message>
        <source>Viewport</source>
        <translation>Vue</translation>
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
R %3  V %4  B %5 (linéaire)</translation>
    </message>
</context>
<context>
    <name>glint::editor::SceneLoader</name>
    <message>
        <source>reading the glTF file</source>
        <translation>lecture du fichier glTF</translation>
    </message>
    <message>
        <source>running the importer</source>
        <translation>exécution de l'importateur</translation>
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
        <translation>Vide</translation>
    </message>
    <message>
        <source>Sun and sky</source>
        <translation>Soleil et ciel</translation>
    </message>
    <message>
        <source>Cornell box</source>
        <translation>Boîte de Cornell</translation>
    </message>
    <message>
        <source>Cornell box in fog</source>
        <translation>Boîte de Cornell dans le brouillard</translation>
    </message>
    <message>
        <source>Portals</source>
        <translation>Portails</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimeRuler</name>
    <message>
        <source>Time ruler</source>
        <translation>Règle temporelle</translation>
    </message>
</context>
<context>
    <name>glint::editor::TimelinePanel</name>
    <message>
        <source>Timeline</source>
        <translation>Chronologie</translation>
    </message>
    <message>
        <source>Path camera</source>
        <translation>Caméra du trajet</translation>
    </message>
    <message>
        <source>  %1 s  (frame %2)</source>
        <translation>  %1 s  (image %2)</translation>
    </message>
    <message>
        <source>Add key</source>
        <translation>Ajouter une clé</translation>
    </message>
    <message>
        <source>Add a camera-path key from the current view at the current time</source>
        <translation>Ajoute une clé de trajet de caméra depuis la vue actuelle à l'instant actuel</translation>
    </message>
    <message>
        <source>Delete key</source>
        <translation>Supprimer la clé</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Lecture</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Boucle</translation>
    </message>
    <message>
        <source>Constant speed</source>
        <translation>Vitesse constante</translation>
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
        <translation>Champ de vision</translation>
    </message>
    <message>
        <source>Focus</source>
        <translation>Mise au point</translation>
    </message>
    <message>
        <source>Lens</source>
        <translation>Objectif</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Temps</translation>
    </message>
    <message>
        <source>Key %1</source>
        <translation>Clé %1</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <source>Key transform</source>
        <translation>Clé de transformation</translation>
    </message>
    <message>
        <source>Key the selected nodes' position, rotation and scale at the current time (K)</source>
        <translation>Pose une clé pour la position, la rotation et l'échelle des nœuds sélectionnés à l'instant actuel (K)</translation>
    </message>
    <message>
        <source>Copy key</source>
        <translation>Copier la clé</translation>
    </message>
    <message>
        <source>Paste key</source>
        <translation>Coller la clé</translation>
    </message>
    <message>
        <source>Key the selected nodes at the current time with the copied key's transform</source>
        <translation>Pose une clé sur les nœuds sélectionnés à l'instant actuel avec la transformation de la clé copiée</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paliers</translation>
    </message>
    <message>
        <source>Cubic</source>
        <translation>Cubique</translation>
    </message>
    <message>
        <source>Auto key</source>
        <translation>Clé automatique</translation>
    </message>
    <message>
        <source>Key every moved, turned or scaled node at the current time (nodes with keys are always keyed)</source>
        <translation>Poser une clé sur chaque nœud déplacé, tourné ou mis à l'échelle au temps courant (les nœuds qui ont des clés en reçoivent toujours une)</translation>
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
        <translation>Solide</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>Fil de fer</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normales</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albédo</translation>
    </message>
    <message>
        <source>Ambient occlusion</source>
        <translation>Occlusion ambiante</translation>
    </message>
    <message>
        <source>Motion vectors</source>
        <translation>Vecteurs de mouvement</translation>
    </message>
    <message>
        <source>Variance</source>
        <translation>Variance</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Profondeur</translation>
    </message>
    <message>
        <source>BVH instance boxes</source>
        <translation>Boîtes BVH des instances</translation>
    </message>
    <message>
        <source>BVH traversal cost (heat map)</source>
        <translation>Coût de parcours BVH (carte de chaleur)</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>Vue</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Déplacer</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Pivoter</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Mettre à l'échelle</translation>
    </message>
    <message>
        <source>Frame selection</source>
        <translation>Cadrer la sélection</translation>
    </message>
    <message>
        <source>Make scene camera from view</source>
        <translation>Créer une caméra de scène depuis la vue</translation>
    </message>
    <message>
        <source>Look through selected camera</source>
        <translation>Voir par la caméra sélectionnée</translation>
    </message>
    <message>
        <source>Snap (Ctrl inverts while dragging)</source>
        <translation>Magnétisme (Ctrl inverse pendant le glisser)</translation>
    </message>
    <message>
        <source>Pixel inspector</source>
        <translation>Inspecteur de pixels</translation>
    </message>
    <message>
        <source>Take snapshot A</source>
        <translation>Prendre l'instantané A</translation>
    </message>
    <message>
        <source>Set render region</source>
        <translation>Définir la région de rendu</translation>
    </message>
    <message>
        <source>Drag a rectangle: the path tracer renders only inside it</source>
        <translation>Tracez un rectangle : le path tracer ne rend qu'à l'intérieur</translation>
    </message>
    <message>
        <source>Clear render region</source>
        <translation>Effacer la région de rendu</translation>
    </message>
    <message>
        <source>Compare A | B</source>
        <translation>Comparer A | B</translation>
    </message>
    <message>
        <source>Pick focus distance</source>
        <translation>Choisir la distance de mise au point</translation>
    </message>
    <message>
        <source>Click a surface: the camera looked through focuses at its depth</source>
        <translation>Cliquez sur une surface : la caméra à travers laquelle vous regardez fait la mise au point à sa profondeur</translation>
    </message>
    <message>
        <source>Pick focus works through a scene camera: select one and look through it (0) first.</source>
        <translation>Le choix de la mise au point passe par une caméra de la scène : sélectionnez-en une et regardez à travers (0) d'abord.</translation>
    </message>
    <message>
        <source>Click the surface to focus on (Esc cancels).</source>
        <translation>Cliquez sur la surface à mettre au point (Échap annule).</translation>
    </message>
    <message>
        <source>Pause viewport rendering</source>
        <translation>Mettre en pause le rendu de la vue</translation>
    </message>
    <message>
        <source>Stop adding samples; edits are still shown at full resolution</source>
        <translation>Cesse d'ajouter des échantillons ; les modifications restent affichées en pleine résolution</translation>
    </message>
    <message>
        <source>Denoise still image</source>
        <translation>Débruiter l'image fixe</translation>
    </message>
    <message>
        <source>Filter the accumulated image while it converges (off: the raw running mean; renders are never filtered)</source>
        <translation>Filtrer l'image accumulée pendant qu'elle converge (désactivé : la moyenne brute ; les rendus ne sont jamais filtrés)</translation>
    </message>
    <message>
        <source>coarse (1/%1 resolution)</source>
        <translation>grossier (résolution 1/%1)</translation>
    </message>
    <message>
        <source>refining to full resolution: %1%</source>
        <translation>affinage en pleine résolution : %1%</translation>
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
        <translation>%1 spp, convergée (limite d'échantillons de la vue)</translation>
    </message>
    <message>
        <source>%1 spp, paused</source>
        <translation>%1 spp, en pause</translation>
    </message>
    <message>
        <source>%1  |  %2 ms/frame</source>
        <translation>%1  |  %2 ms/image</translation>
    </message>
    <message>
        <source>Local axes</source>
        <translation>Axes locaux</translation>
    </message>
    <message>
        <source>Move and rotate along the selected node's own axes (off: the world's)</source>
        <translation>Déplacer et tourner selon les axes propres du nœud sélectionné (désactivé : ceux du monde)</translation>
    </message>
    <message>
        <source>up to %1 spp, converged (noise threshold)</source>
        <translation>jusqu'à %1 spp, convergée (seuil de bruit)</translation>
    </message>
    <message>
        <source>%1, %2% converged</source>
        <translation>%1, %2% convergé</translation>
    </message>
</context>
</TS>