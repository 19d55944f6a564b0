# La liste des leçons et le panneau de la leçon à côté des tracés.

## La liste de l’onglet Leçons

lesson-numbered-title = { $number }. { $title }
lesson-list-question = Question : { $question }
lesson-start = Commencer la leçon { $number }

## Le panneau de la leçon

lesson-count = Leçon { $number } sur { $count }
lesson-run = {" "}· simulation { $run }
lesson-look-head = Ce qu’il faut observer
lesson-question-head = Question
lesson-hint = Indice
lesson-show-answer = Afficher la réponse (pour l’enseignant)
lesson-previous = ← Précédent
lesson-next = Suivant →
lesson-close = Fermer la leçon
lesson-copy-link-short = Copier le lien
lesson-copy-link-rest = {" "}vers cette leçon
lesson-link-copied = Lien copié : il ouvre cette leçon et sa simulation.
lesson-copy-this-link = Copiez ce lien : { $link }
lesson-load-run = Charger la simulation de la leçon
lesson-own-settings = Ce lien contient ses propres réglages ; ils sont affichés tels qu’il les donne, à la place de ceux de la simulation de la leçon : { $differences }. Ce que la leçon dit de sa simulation ne vaut pas forcément pour eux.
