# El recorrido por el diseño (web/teaching/walkthrough*.js). Las ecuaciones no están aquí: se
# mantienen como las escribe el artículo. Una llave del texto (como en u_{"{"}k−1{"}"}) se escribe
# {"{"} y {"}"}.

## Section model (walkthrough-text.js): 1. The motor model (2)

walkthrough-model-title = 1. El modelo del motor (2)
walkthrough-model-prose-1 = El estado lo forman la velocidad del rotor ω = x1, las corrientes estatóricas i_sa, i_sb = x2, x3 y las componentes del flujo rotórico φ_ra, φ_rb = x4, x5 en la referencia estacionaria a–b. Solo se miden las corrientes; las tensiones u1, u2 son las entradas.
walkthrough-model-prose-2 = El par dividido por la inercia es a1(x3·x4 − x2·x5), en rad/s²: el producto vectorial de la corriente y el flujo (a1 = 3n_pM/(2JL_r) ya contiene 1/J, así que hay que multiplicar por J para obtener N m). La carga a2 + a3·x1 es la constante T0 más el rozamiento Cf·ω, divididos por J. El núcleo calcula los parámetros agrupados siguientes a partir de los parámetros del motor en uso; la planta (el motor simulado) y el modelo (lo que suponen el EKF y el controlador) pueden diferir.
walkthrough-model-note = Aquí σ está en henrios: la σ = L_s − M²/L_r del artículo es la inductancia de dispersión total vista desde el estátor (la inductancia transitoria), no la dispersión propia del estátor L_s − M; muchos textos usan en su lugar la σ adimensional σ = 1 − M²/(L_sL_r).
walkthrough-model-plot-title = Velocidad y flujo

## Section ekf (walkthrough-text.js): 2. The extended Kalman filter (10)–(20)

walkthrough-ekf-title = 2. El filtro de Kalman extendido (10)–(20)
walkthrough-ekf-prose-1 = El EKF estima los cinco estados a partir de las corrientes medidas y las tensiones aplicadas. Predice con el modelo discretizado por Euler explícito (10), linealizado mediante el jacobiano (11), y corrige con la innovación: las corrientes medidas menos las predichas.
walkthrough-ekf-prose-2 = Q (ruido de proceso: q·Ts en cada estado, más q_speed·Ts solo en la velocidad) indica cuánto se confía en el modelo; R (ruido de medida, r_std²·I), cuánto en los sensores. Un único q para estados de unidades distintas es la elección del artículo; q_speed permite que la estimación de velocidad se mueva sin relajar el resto. La ganancia K_k entra en el controlador como la ganancia del observador L = K_k/Ts de la forma general (4): los errores de estimación x̃ son lo que el controlador debe tolerar.
walkthrough-ekf-prose-3 = Un filtro consistente tiene sus innovaciones dentro de su banda de ±2σ alrededor del 95 % del tiempo y un cuadrado normalizado de la innovación (NIS) de media 2. Los intervalos y las cotas de este recorrido abarcan { $wt-ekf-euler-nis--draws } realizaciones del ruido (semillas 1 a { $wt-ekf-euler-nis--draws }). El predictor de Euler no puede seguir corrientes de 200 Hz: en sine200 su NIS medio es al menos { $wt-ekf-euler-nis } en todas las realizaciones, y el del predictor RK4 como mucho { $wt-ekf-rk4-nis }; compáralos abajo.
walkthrough-ekf-prose-4 = La sección 3.1 propone un remedio que no llega a construir: tratar las magnitudes que varían lentamente como estados adicionales. El mando ekf.load añade a2 = T_L0/J como paseo aleatorio (el controlador usa entonces â2 y su derivada, la inyección l_a·(x̃2, x̃3)); ekf.rr añade la resistencia rotórica (las a5, a7, a8, a10 del controlador siguen a R̂_r). Las dos últimas gráficas muestran ambas estimaciones, con sus bandas de ±2σ obtenidas de P, frente al valor real. Un estado adicional absorbe todo lo que le falta al modelo, con razón o sin ella: un estado de resistencia rotórica ante una carga desconocida toma la carga por una resistencia (véanse las lecciones).
walkthrough-ekf-note = La (13) impresa predice con u_{"{"}k|k−1{"}"}; la tensión que actuó durante la última muestra es u_{"{"}k−1{"}"}, que es la que usa (10) y también el filtro de aquí. La forma de Joseph escribe la actualización de la covarianza (19) como suma de dos términos simétricos, cada uno semidefinido positivo para cualquier ganancia K: el redondeo tiene mucha menos capacidad de hacer que P pierda cualquiera de las dos propiedades que en la forma corta (I − K_kC)P_{"{"}k|k−1{"}"}, aunque nada lo garantiza.
walkthrough-ekf-plot-title = Innovación ỹ_a con su banda de ±2σ obtenida de S_k
walkthrough-ekf-plot4-title = Cuadrado normalizado de la innovación con su banda del 95 % (χ², 2 grados de libertad)
walkthrough-ekf-plot2-title = Estimación de velocidad y su varianza
walkthrough-ekf-plot3-title = Módulo del flujo: real y estimado
walkthrough-ekf-plot5-title = Par de carga: estimación â2·J con su banda de ±2σ, y valor real
walkthrough-ekf-plot6-title = Resistencia rotórica: estimación con su banda de ±2σ, y la del motor

## Section bridge (walkthrough-text.js): 3. From the observer to the controller: (4) and (5)

walkthrough-bridge-title = 3. Del observador al controlador: (4) y (5)
walkthrough-bridge-prose-1 = El controlador nunca ve el estado del motor, solo la estimación x̂ del observador y las corrientes medidas x2, x3. Sea el error de estimación x̃ = x − x̂. Dos de sus componentes se miden: los residuos de corriente x̃2 = x2 − x̂2 y x̃3 = x3 − x̂3. Tres no: el error de velocidad x̃1 y los errores de flujo x̃4, x̃5.
walkthrough-bridge-prose-2 = El artículo diseña el controlador frente a un observador de la forma general (4): el modelo (2) copiado con las estimaciones, más una inyección si_i = l_i1·x̃2 + l_i2·x̃3 (5), una corrección que desplaza cada estimación según los residuos medidos. Leída como un paso de Euler explícito, la actualización del EKF tiene esta forma con L = K_k/Ts y el residuo a priori y_k − Cx̂_{"{"}k|k−1{"}"} (15), en las filas 2 a 5. La fila 1, solo aproximadamente: el término de par del EKF usa las corrientes estimadas x̂2, x̂3 donde (4) usa las medidas x2, x3. El controlador de aquí usa el residuo a posteriori y_k − Cx̂_{"{"}k|k{"}"} = (I − CK_k)(y_k − Cx̂_{"{"}k|k−1{"}"}), que corresponde a x̃ = x − x̂ para la estimación a posteriori x̂_{"{"}k|k{"}"} que usa; ambos coinciden solo mientras CK_k es pequeño.
walkthrough-bridge-prose-3 = Restar (4) de (2) da la dinámica del error que se muestra abajo. El controlador deriva los residuos medidos (están en v1 y en ψ3), y sus derivadas contienen los no medidos x̃1, x̃4, x̃5. Cada una de esas derivadas se divide en dos: la dinámica nominal de los residuos, lo que serían ẋ̃2 y ẋ̃3 con x̃1 = x̃4 = x̃5 = 0, que el controlador calcula, y el resto, que no puede calcular. El diseño toma además L como constante: L̇ se desprecia en todo lo que sigue.
walkthrough-bridge-prose-4 = Ese es el diseño integrado que da título al artículo: la dinámica del error del observador está dentro del diseño del controlador, y los términos desconocidos aparecen solo donde se deriva una corriente medida o un residuo, en el paso 2 (ż2 contiene ẋ2, ẋ3 y v̇1) y en el paso 4 (ż4 contiene las derivadas de las inyecciones si4, si5); los pasos 1 y 3 no tienen ninguno. En aquellos dos pasos se agrupan como d̃2 y d̃4 y se tratan como perturbaciones acotadas. Con un modelo exacto, esos son todos; un modelo que difiere del motor añade términos propios a ż2 y ż4, que los d̃2 y d̃4 del artículo no tienen.
walkthrough-bridge-prose-5 = Lo que sustituye la integración es la separación de escalas de tiempo que menciona el resumen del artículo: un observador tanto más rápido que el controlador que este puede tratar su estimación como si fuera el estado. Las leyes de abajo siguen poniendo x̂ donde una ley de realimentación del estado pondría x, la forma de la equivalencia cierta; lo que añade el diseño es que los errores de estimación entran en su argumento de Lyapunov, como d̃2 y d̃4 acotados bajo la hipótesis 4.2, en lugar de suponerse nulos.
walkthrough-bridge-figure = El controlador y el observador, como en la Fig. 1 del artículo: el controlador solo ve el motor a través de la estimación, la ganancia y los residuos del EKF, y de las corrientes medidas.
    .alt = Diagrama de bloques: la referencia y la estimación, la ganancia y los residuos del EKF entran en el controlador backstepping; su tensión pasa por el límite de tensión y acciona el motor; las corrientes medidas y la tensión aplicada vuelven al EKF.
walkthrough-bridge-note = El artículo escribe si_i(x̃2, x̃3) para la inyección; aquí si_i es su valor l_i1·x̃2 + l_i2·x̃3. La letra ψ designa tanto la consigna de flujo ψ_d como los términos conocidos ψ2, ψ3, ψ4 de los pasos siguientes: no tienen relación entre sí.

## Section step1 (walkthrough-text.js, walkthrough-laws.js): 4. Step 1: the speed loop

walkthrough-step1-title = 4. Paso 1: el lazo de velocidad
walkthrough-step1-prose-1 = El paso 1 regula la velocidad estimada: z1 = x̂1 − ω_d. Su derivada, a partir de la primera línea de (4), es el lazo abierto (23). Se descompone el término de rozamiento en torno a la referencia, −a3·x̂1 = −a3·z1 − a3·ω_d: el amortiguamiento propio del motor −a3·z1 se conserva, y −a3·ω_d es un término conocido.
walkthrough-step1-prose-2 = Un control virtual es una señal que un paso trata como su entrada aunque el motor no tenga tal entrada. El del paso 1 es el término de par a1(x3·x̂4 − x2·x̂5), formado por corrientes medidas y flujos estimados: se le pide que sea igual a v1 (un par dividido por la inercia, en rad/s²) y se llama z2 a lo que le falta (24). Entonces se cumple (25).
walkthrough-step1-prose-3 = Se elige v1 = v1a + v1s (26). La prealimentación v1a (27) cancela todos los términos conocidos; si1 es conocido, ya que solo usa los residuos medidos. La realimentación v1s = −k1s1·z1 (28) deja (29), ż1 = −k1·z1 + z2 con k1 = a3 + k1s1: k1s1 es la parte de la tasa k1 que el controlador añade al amortiguamiento propio del motor a3, y por eso v1a contiene a3·ω_d y no a3·x̂1. Los pasos 1 y 2 conservan el amortiguamiento propio del motor; los pasos 3 y 4 cancelan todo lo que conocen.
walkthrough-step1-prose-4 = La función de Lyapunov del paso 1 es V1 = ½z1². A lo largo de (29), V̇1 = z1ż1 = −k1z1² + z1z2: negativa salvo por el término cruzado z1z2, que cancela el paso 2.
walkthrough-step1-prose-5 = El paso 2 necesita v̇1. Se deriva (30) con L constante (despreciando L̇): la derivada de la inyección es l11·ẋ̃2 + l12·ẋ̃3, y ẋ̃2, ẋ̃3 contienen los no medidos x̃1, x̃4, x̃5 (sección 3). La parte conocida de v̇1 pone en su lugar la dinámica nominal de los residuos; el resto, los «…» de abajo, va a d̃2.
walkthrough-step1-note = La (31) impresa tiene a3·ω_d y â2 donde corresponden a3·ω̇_d y dâ2/dt (corregido arriba). Los «…» son los términos en x̃1, x̃4, x̃5: −(l11·a5 − l12·a6·x̂1)·x̃4 − (l12·a5 + l11·a6·x̂1)·x̃5 − (l11·a6·x5 − l12·a6·x4)·x̃1.
walkthrough-step1-plot-title = Paso 1: z1, v1 = v1a + v1s y el término de par
walkthrough-step1-plot3-title = Paso 1: ż1 tal como la produjo la ejecución (su variación en cada muestra, dividida por Ts) frente a la diseñada −k1·z1 + z2
walkthrough-law-1-intro = Deduce v1 tú mismo y escríbelo abajo como fórmula con los nombres de esta sección (x1h para x̂1, wd y dwd para ω_d y ω̇_d, si1, a2, a3, k1s1, z1; la lista completa está abajo), con + − * / ^, paréntesis y funciones. Se ejecuta a 20 kHz en lugar de la (26) del artículo en cuanto pulsas Intro o dejas de escribir; un campo vacío restablece la ley del artículo. Tras la ejecución, el veredicto comprueba tu ley frente a la dinámica diseñada ż1 = −k1·z1 + z2 en estados y valores de parámetros sorteados, y la gráfica de abajo muestra su residuo a lo largo de la ejecución: cero para una ley que la cumple.
walkthrough-law-1-plot-title = Paso 1: el residuo de tu ley, ż1 frente a la diseñada ż1 = −k1·z1 + z2 (tu v1 menos el del artículo)

## Section step2 (walkthrough-text.js, walkthrough-laws.js): 5. Step 2: the torque loop

walkthrough-step2-title = 5. Paso 2: el lazo de par
walkthrough-step2-prose-1 = El paso 2 hace que el término de par siga a v1 llevando z2 a cero, y aquí aparecen por primera vez las tensiones. Se deriva (24): ẋ2 y ẋ3 aportan bu1 y bu2, de modo que la entrada es v2 = b·a1(x̂4·u2 − x̂5·u1); x̂̇4, x̂̇5 son las de (4); y −v̇1 es (31). Se agrupa en ψ2 lo que el controlador conoce y se escribe el término de par como z2 + v1: resulta (32).
walkthrough-step2-prose-2 = ψ2 reúne todo lo conocido: la dinámica del flujo y de las corrientes, las inyecciones si4, si5 y la parte conocida de v̇1. Los errores no medidos x̃1, x̃4, x̃5 entran solo a través de d̃2 (33) (con un modelo exacto; un modelo que difiere del motor añade términos propios a ż2): es lineal en ellos, con coeficientes formados a partir de x̂, x y L, y por tanto está acotado mientras lo estén x̂, x, L y x̃. El artículo mantiene x̂ acotada con una proyección (7)–(9); eso acota x̂, no x̃, y mientras actúa la proyección x̂̇ ya no es (4), ni ψ2–ψ4 son exactos. El EKF de aquí no tiene proyección: nada salvo la propia ejecución acota x̂.
walkthrough-step2-prose-3 = Se elige v2 = v2a + v2s (34): v2a = −ψ2 − z1 cancela los términos conocidos y el término cruzado z1z2 de V̇1; v2s = −k2s1·z2 + v2s2 (36) añade la realimentación, con k2 = a7 + a8 + k2s1, ya que el propio motor aporta el amortiguamiento a7 + a8. Para el motor del artículo, a7 + a8 = 232,7 /s, así que k2s1 = 967,3 /s cuando k2 = 1200 /s.
walkthrough-step2-prose-4 = El término robusto v2s2 = −h2²z2/(4ε2) (38) domina a d̃2 si h2 acota |d̃2|. Con V_s2 = ½(z1² + z2²) (39), V̇_s2 = −k1z1² − k2z2² + z2(v2s2 + d̃2) ≤ −k1z1² − k2z2² + ε2 (40). Ningún h2 finito lo consigue para un d̃2 que crece sin límite: en cuanto |d̃2| supera h2, z2(v2s2 + d̃2) puede superar ε2.
walkthrough-step2-prose-5 = Qué términos van a d̃2 es una elección: (33) escribe la velocidad real como x1 = x̂1 + x̃1 y deja la parte en x̂1 en ψ2; otra división movería términos entre ψ2 y d̃2 y dejaría ż2 igual. La hipótesis 4.2 (22) es aquello en lo que se apoya aquí el artículo: supone que x̃ está en una caja conocida [x̃_min, x̃_max], afirma que entonces d̃2 está acotado y toma h2 igual a esa cota (38), como el paso 4 toma h4 (53). No da ningún valor para la caja ni para las cotas. Aquí h2 y h4 son ajustes; la gráfica de d̃2 de abajo y la de d̃4 del paso 4 miden los términos en la ejecución mostrada, una forma de dimensionarlos para esa ejecución. ε2 equilibra entonces el suelo ε/λ de (59) frente a la tasa h2²/(4ε2) que v2s2 añade a la de z2, y un lazo muestreado cada Ts solo sostiene una tasa bastante inferior a unos 2/Ts; la lección «Los términos robustos y la cota (59)» desarrolla una elección concreta.
walkthrough-step2-prose-6 = Al derivar z2 aparece también −(a7 + a8)·z2, el amortiguamiento propio del motor; la (32) impresa lo omite, y el k2 = a7 + a8 + k2s1 de (36) lo tiene en cuenta.
walkthrough-step2-note = La (35) impresa es v2a = −ψ2 − d̃2 − z1: d̃2 es desconocido, así que ningún controlador puede restarlo; el controlador de aquí usa −ψ2 − z1 y deja d̃2 al término robusto.
walkthrough-step2-shows-1 = La gráfica de abajo evalúa d̃2 a partir de la verdad simulada: la ż2 real del motor menos los términos que conoce el controlador, con las corrientes reales en lugar de las medidas. Se evalúa para el EKF de cinco estados sin compensación del retardo; para un observador con estados adicionales (ekf.load, ekf.rr) o con delay.comp, la gráfica queda vacía. h2 debe ser al menos el pico de |d̃2| para que (38) lo domine: léelo en step con un modelo exacto y después con un error de modelo (plant.j, plant.rr). Con la R_r del motor un 10 % por encima de la del modelo (plant.rr = 5.445), el lazo se desboca o falla en { $wt-rrhigh-runaway } de { $wt-rrhigh-runaway--draws } realizaciones: el flujo se dispara en { $wt-rrhigh-off } y el controlador falla antes del final en { $wt-rrhigh-fail }. El flujo termina los 0,1 s del preajuste en { $wt-rrhigh-flux-min } a { $wt-rrhigh-flux-max } Wb y vale de { $wt-rrhigh1s-flux-min } a { $wt-rrhigh1s-flux-max } Wb tras 1 s, y los coeficientes de d̃2 en (33) crecen con x.
walkthrough-step2-plot-title = Paso 2: z2 y v2 = v2a + v2s
walkthrough-step2-plot2-title = Paso 2: d̃2 evaluado a partir de la verdad simulada, frente a ±h2
walkthrough-step2-plot3-title = Paso 2: ż2 tal como la produjo la ejecución (su variación en cada muestra, dividida por Ts) frente a la diseñada −k2·z2 − z1 (con su término robusto cuando robust=1)
walkthrough-law-2-intro = Deduce v2 tú mismo y escríbelo abajo como fórmula con los nombres de esta sección (v1 y z2 (del paso 1), x2 y x3, x4h y x5h, si4 y si5, dxt2 y dxt3, l11 y l12, ddwd, a1 hasta a10, k1, k1s1, k2s1; la lista completa está abajo), con + − * / ^, paréntesis y funciones. Se ejecuta a 20 kHz en lugar de la (34) del artículo en cuanto pulsas Intro o dejas de escribir; un campo vacío restablece la ley del artículo. Si has escrito tu propio v1 bajo el paso 1, tu v2 se juzga sobre él: debe derivar tu v1, con la ż1 que da tu v1. Tras la ejecución, el veredicto comprueba tu ley frente a la dinámica diseñada ż2 = −k2·z2 − z1 en estados y valores de parámetros sorteados, y la gráfica de abajo muestra su residuo a lo largo de la ejecución: cero para una ley que la cumple.
walkthrough-law-2-plot-title = Paso 2: el residuo de tu ley, ż2 frente a la diseñada ż2 = −k2·z2 − z1 (tu v2 menos el v2 que la da: el del artículo o, tras tu propio v1, el que deriva el tuyo)

## Section step3 (walkthrough-text.js, walkthrough-laws.js): 6. Step 3: the flux outer loop

walkthrough-step3-title = 6. Paso 3: el lazo exterior de flujo
walkthrough-step3-prose-1 = El paso 3 regula el cuadrado del módulo del flujo estimado: z3 = x̂4² + x̂5² − ψ_d (42). Su derivada solo necesita (4): ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5 − ψ̇_d, en la que se cancelan los términos en a9, escrita abajo solo en función de las estimaciones. Escribir x̂2 = x2 − x̃2 y x̂3 = x3 − x̃3 separa el control virtual 2a10(x2·x̂4 + x3·x̂5), la parte de ż3 que imponen las corrientes estatóricas, de ψ3 (43).
walkthrough-step3-prose-2 = ψ3 solo depende de estimaciones y de residuos medidos, así que el paso 3 no tiene ningún término desconocido: con v3 = −ψ3 − k3·z3 (45), ż3 = −k3·z3 + z4 (46) se cumple exactamente en tiempo continuo, para la propia estimación de flujo del observador. Su función de Lyapunov es V3 = ½z3², con V̇3 = −k3z3² + z3z4; el paso 4 cancela el término cruzado.
walkthrough-step3-prose-3 = Como v3 = −ψ3 − k3·z3, el error siguiente z4 (44) es z4 = ż3 + k3·z3: la medida en que z3 no decae con la tasa k3.
walkthrough-step3-prose-4 = El artículo escribe la realimentación como v3s = −k3s1·z3 y toma k3 = k3s1 (46): v3a cancela todo ψ3, incluido el decaimiento propio del flujo −2a8·(x̂4² + x̂5²), de modo que toda la tasa k3 la pone el controlador, mientras que en el paso 1 el amortiguamiento del motor a3 forma parte de k1.
walkthrough-step3-note = El planteamiento del problema pide que x4² + x5² siga a ψ_d², pero (42) resta ψ_d: aquí ψ_d es la consigna del cuadrado del módulo, en Wb². El psi_d del escenario es esa consigna: psi_d = 0.5 Wb² pide un módulo del flujo |φ| = 0,707 Wb. Las simulaciones del artículo dan «ϕ_d = 0,5» como módulo del flujo deseado, que leído literalmente son 0,5 Wb (0,25 Wb²); los preajustes lo toman como el cuadrado del módulo, tal como lo usa (42): el cuadrado del flujo inicial del artículo, [0,5; 0,5].
walkthrough-step3-shows-1 = La gráfica de z3 muestra el error de la propia estimación de flujo del observador respecto a la consigna, no el del motor. En step con un modelo exacto, a partir de 15 ms, su RMS es de { $wt-z3-min } a { $wt-z3-max } mWb² con el EKF y de { $wt-z3-quiet } mWb² sin ruido de medida (noise=0): el ruido entra en z3 a través de las innovaciones. Con el observador perfecto (perfect=1), cuya estimación es el flujo del motor, se mantiene por debajo de { $wt-z3-perfect-max } mWb².
walkthrough-step3-plot-title = Paso 3: z3 y v3 = v3a + v3s
walkthrough-step3-plot3-title = Paso 3: ż3 tal como la produjo la ejecución (su variación en cada muestra, dividida por Ts) frente a la diseñada −k3·z3 + z4
walkthrough-law-3-intro = Deduce v3 tú mismo y escríbelo abajo como fórmula con los nombres de esta sección (x4h y x5h, xt2 y xt3, si4 y si5, a8, a10, k3, z3; la lista completa está abajo), con + − * / ^, paréntesis y funciones. Se ejecuta a 20 kHz en lugar de la (45) del artículo en cuanto pulsas Intro o dejas de escribir; un campo vacío restablece la ley del artículo. Tras la ejecución, el veredicto comprueba tu ley frente a la dinámica diseñada ż3 = −k3·z3 + z4 en estados y valores de parámetros sorteados, y la gráfica de abajo muestra su residuo a lo largo de la ejecución: cero para una ley que la cumple.
walkthrough-law-3-plot-title = Paso 3: el residuo de tu ley, ż3 frente a la diseñada ż3 = −k3·z3 + z4 (tu v3 menos el del artículo)

## Section step4 (walkthrough-text.js, walkthrough-laws.js): 7. Step 4: the flux inner loop and the voltages

walkthrough-step4-title = 7. Paso 4: el lazo interior de flujo y las tensiones
walkthrough-step4-prose-1 = El paso 4 lleva z4 a cero; su entrada v4 = 2a10·b(x̂4·u1 + x̂5·u2) es la segunda combinación de las tensiones. Como z4 = ż3 + k3·z3, ż4 = z̈3 + k3·ż3 = z̈3 + k3(−k3z3 + z4). Se deriva ż3 una vez más en su forma solo en función de las estimaciones (la primera línea del paso 3), no en la forma (43), cuyas corrientes medidas introducirían términos desconocidos que se cancelan: los términos en x̂̇4, x̂̇5 se agrupan como abajo, x̂̇2 y x̂̇3 aportan las tensiones (v4) y la dinámica de las corrientes, y las derivadas de las inyecciones, l41·ẋ̃2 + l42·ẋ̃3 y l51·ẋ̃2 + l52·ẋ̃3, aportan las derivadas de los residuos.
walkthrough-step4-prose-2 = En la derivada de 2a10·(x2·x̂4 + x3·x̂5), los términos en a6 de ẋ2 y ẋ3 (2) se cancelan en su parte conocida, a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0, y por eso ψ4 no tiene a6; el resto, que contiene x̃1, x̃4, x̃5, va a d̃4. Con V_s4 = ½z3² + ½z4² (56), V̇_s4 = −k3z3² − k4z4² + z4(v4s2 + d̃4) ≤ −λ4·V_s4 + ε4 con λ4 = 2·min(k3, k4), que al integrarse da (57), como hace la sección 8 para V.
walkthrough-step4-prose-3 = ψ4 toma la dinámica nominal de los residuos para ẋ̃2 y ẋ̃3 (sección 3), despreciando L̇: la (47) impresa se cumple con L̇ = 0. Lo que deja fuera la dinámica nominal, los términos en x̃1, x̃4, x̃5 de ẋ̃2 y ẋ̃3 ponderados por 2(l41·x̂4 + l51·x̂5) y 2(l42·x̂4 + l52·x̂5), es d̃4.
walkthrough-step4-prose-4 = Se elige v4 = −ψ4 − z3 − k4·z4 + v4s2 (49)–(51): el −z3 cancela el término cruzado z3z4 de V̇3, y resulta (52). v2 y v4 juntos fijan ambas tensiones a través de la matriz de desacoplamiento (54), invertible mientras el flujo estimado no sea nulo (55). Después actúa el límite de tensión: el artículo solo da un límite de 400 V; la caja (vlimit=box) recorta cada componente a ±400 V, mientras que el círculo y el hexágono del inversor (vlimit) reducen el vector entero a escala, conservando su dirección. Mientras actúa, la dinámica del error diseñada deja de cumplirse.
walkthrough-step4-note = La (48) impresa tiene a21, a22 donde corresponden a41, a42 (corregido arriba). El ψ4 de arriba es la (47) impresa reagrupada: el artículo escribe 2a10(l21·x̃2·x̂4 + …) por 2a10(x̂4·si2 + x̂5·si3), y divide en dos cada producto con x̂̇4, x̂̇5. Su d̃4 es el mismo que el impreso, término a término.
walkthrough-step4-shows-1 = |d̃4|, evaluado a partir de la verdad simulada como d̃2, se representa abajo frente a ±h4; h4 debe ser al menos su pico para que (53) lo domine.
walkthrough-step4-shows-2 = En sus primeros 5 ms, el transitorio de arranque pide tensiones muy por encima del límite: la u_sa de mando alcanza picos de { $wt-cmd-step-min } a { $wt-cmd-step-max } V en step y de { $wt-cmd-rr-min } a { $wt-cmd-rr-max } V en rr-mismatch (el preajuste de la discrepancia), y en rr-mismatch el límite recorta el mando hasta los { $wt-clip-rr-min } a { $wt-clip-rr-max } ms. Las gráficas ajustan sus ejes y a la ejecución posterior a ese transitorio; desmarca «Ajustar los ejes y tras el transitorio de arranque», encima de las gráficas, para verlo.
walkthrough-step4-plot-title = Paso 4: z4, v4 y la tensión antes y después del límite
walkthrough-step4-plot2-title = Paso 4: d̃4 evaluado a partir de la verdad simulada, frente a ±h4
walkthrough-step4-plot3-title = Paso 4: ż4 tal como la produjo la ejecución (su variación en cada muestra, dividida por Ts) frente a la diseñada −k4·z4 − z3 (con su término robusto cuando robust=1)
walkthrough-law-4-intro = Deduce v4 tú mismo y escríbelo abajo como fórmula con los nombres de esta sección (v3 y z4 (del paso 3), dx4h y dx5h, dxt2 y dxt3, si2 hasta si5, l41 hasta l52, a5, a7, a8, a10, k3, k4, z3; la lista completa está abajo), con + − * / ^, paréntesis y funciones. Se ejecuta a 20 kHz en lugar de la (49) del artículo en cuanto pulsas Intro o dejas de escribir; un campo vacío restablece la ley del artículo. Si has escrito tu propio v3 bajo el paso 3, tu v4 se juzga sobre él: debe derivar tu v3, con la ż3 que da tu v3. Tras la ejecución, el veredicto comprueba tu ley frente a la dinámica diseñada ż4 = −k4·z4 − z3 en estados y valores de parámetros sorteados, y la gráfica de abajo muestra su residuo a lo largo de la ejecución: cero para una ley que la cumple.
walkthrough-law-4-plot-title = Paso 4: el residuo de tu ley, ż4 frente a la diseñada ż4 = −k4·z4 − z3 (tu v4 menos el v4 que la da: el del artículo o, tras tu propio v3, el que deriva el tuyo)

## Section stability (walkthrough-text.js): 8. Stability: Theorem 4.6

walkthrough-stability-title = 8. Estabilidad: teorema 4.6
walkthrough-stability-prose-1 = Con V = ½(z1² + z2² + z3² + z4²) (58), las cuatro dinámicas del error diseñadas dan V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4) (60). Los términos cruzados ±z1z2 y ±z3z4 se cancelan: para eso están el −z1 de v2a y el −z3 de v4a.
walkthrough-stability-prose-2 = Tres líneas completan la demostración. Primera: si |d̃2| ≤ h2 (h2 = δ_d2 de (38), una cota de d̃2 cuya existencia el artículo afirma a partir de las cotas de x̃ de la hipótesis 4.2 (22), sin deducirla: d̃2 es lineal en x̃1, x̃4, x̃5 con coeficientes que contienen los x1, x4, x5 reales, las estimaciones y las ganancias l11, l12, así que las cotas de x̃ lo acotan solo mientras estos se mantengan acotados), la desigualdad de Young acota el par robusto: z2(v2s2 + d̃2) ≤ h2|z2| − h2²z2²/(4ε2) ≤ ε2, ya que la diferencia es un cuadrado perfecto. Lo mismo vale para z4 con h4 y ε4. Segunda: Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V = λV. Así, V̇ ≤ −λV + ε con ε = ε2 + ε4. Tercera, el paso de comparación: e^(λt)·V tiene la derivada e^(λt)·(V̇ + λV) ≤ ε·e^(λt); integrando de 0 a t se obtiene (59).
walkthrough-stability-prose-3 = V suma cuadrados de unidades distintas (z1 en rad/s, z2 en rad/s², z3 en Wb², z4 en Wb²/s), y ε2 (rad²/s⁵) y ε4 (Wb⁴/s³) también difieren: (59) se cumple para los valores numéricos en el SI. No se traslada tal cual a cualquier ponderación: con V = ½Σw_i·z_i², los términos cruzados de V̇ pasan a ser (w1 − w2)·z1z2 y (w3 − w4)·z3z4, que solo se cancelan si w1 = w2 y w3 = w4 (con pesos desiguales queda un término cruzado, que reduce λ), a menos que los acoplamientos −z1 de (35) y −z3 de (50) se reescalen a −(w1/w2)·z1 y −(w3/w4)·z3. Esos acoplamientos llevan una unidad (1/s² en el SI) que la suma simple oculta. Lo que acota es la suma, y cada ½z_i² solo a través de la suma. La gráfica compara la V registrada con esa cota para esta ejecución.
walkthrough-stability-prose-4 = El teorema acota los errores z_i de las estimaciones, no el motor: el error real de velocidad es |x1 − ω_d| ≤ |z1| + |x̃1|. Supone |d̃2| ≤ h2 y |d̃4| ≤ h4 a lo largo de toda la ejecución; esas mismas cotas presuponen x, x̂ y L acotados, que es lo que concluye el teorema, y los términos en L̇ despreciados no están ni en ψ ni en d̃. No dice nada del motor real cuando la hipótesis no se cumple.
walkthrough-stability-shows-1 = Con el error inicial del 10 % del EKF y un modelo exacto, el límite de tensión contiene el arranque: con él, sine200 se desboca en { $wt-limit-runaway } de { $wt-limit-runaway--draws } realizaciones (con la R_r del motor un 10 % por encima de la del modelo, en { $wt-limit-rrhigh-runaway } incluso con él), pero sin él (vmax=100000), en { $wt-nolimit-runaway }, y termina desviada hasta { $wt-nolimit-off-max } rad/s con el flujo en hasta { $wt-nolimit-flux-max } Wb. Desde una estimación inicial correcta (init_err=0), la misma ejecución sin el límite sigue la referencia con { $wt-exact-rms-min } a { $wt-exact-rms-max } rad/s de RMS en todas las realizaciones con un modelo exacto; con la R_r del motor un 10 % por encima de la del modelo falla aun así: su error RMS es al menos { $wt-exact-rrhigh-rms } rad/s, y se desboca en { $wt-exact-rrhigh-runaway } de { $wt-exact-rrhigh-runaway--draws } realizaciones.
walkthrough-stability-plot-title = Función de Lyapunov V(t) = ½Σz_i² frente a la cota (59), escala logarítmica

## The plots' signals, in their legends (walkthrough-text.js, walkthrough-laws.js)

walkthrough-series-estimated = { $signal } estimado
walkthrough-series-true = { $signal } real
walkthrough-series-right = { $signal } (eje derecho)
walkthrough-series-right-unit = { $signal } ({ $unit }, eje derecho)
walkthrough-series-feedforward = { $term }, prealimentación
walkthrough-series-feedback = { $term }, realimentación
walkthrough-series-run = { $signal }, de la ejecución
walkthrough-series-designed = { $expression }, diseñada
walkthrough-series-load-true = T_L real (T0 + escalón)
walkthrough-series-rr-motor = R_r del motor
walkthrough-series-u-commanded = u_sa de mando (V)
walkthrough-series-u-applied = u_sa aplicada (V)
walkthrough-series-lyapunov = V(t), función de Lyapunov
walkthrough-series-bound = cota (59)
walkthrough-series-law-paper = tu { $output } − el { $output } del artículo
walkthrough-series-law-gives = tu { $output } − el { $output } que da { $rate }
walkthrough-nis-low = cuantil del 2,5 %
walkthrough-nis-high = cuantil del 97,5 %
walkthrough-stability-plot-unit = V (unidades mixtas: ½Σz_i²)

## A section's frame (walkthrough-sections.js, walkthrough.js)

walkthrough-diagram-label = Diagrama de la sección { $section }
walkthrough-equation-label = Ecuación { $number } de la sección { $section }
walkthrough-run-shows = Lo que muestra la ejecución
walkthrough-lumped-label = Parámetros agrupados de la planta y del modelo
walkthrough-lumped-plant = planta
walkthrough-lumped-model = modelo
walkthrough-stability-waiting = Ejecuta un escenario para comparar V con la cota.
walkthrough-compare-button = Comparar los predictores Euler y RK4 en este escenario
walkthrough-compare-label = Comparación de los predictores Euler y RK4
walkthrough-knobs = Mandos del diseño
walkthrough-ifoc-note = Este escenario ejecuta la base de comparación clásica, el IFOC. Los términos del backstepping de abajo se evalúan a partir de la estimación del EKF para comparar; no son lo que acciona el motor.
walkthrough-equations-failed = No se pudieron cargar las ecuaciones: comprueba la conexión y vuelve a abrir el recorrido por el diseño.

## The stability report (walkthrough-reports.js): the bound (59) against V over the run, then
## what it adds when V leaves the bound, by the likely cause. Its sentences are shown one after
## the other, parted by a space.

walkthrough-stability-nothing = No se registró nada.
walkthrough-stability-bound-robust = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (términos robustos activados).
walkthrough-stability-bound-off = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (términos robustos desactivados, así que la cota es V(0)·e^(−λt)).
walkthrough-stability-under =
    V se mantiene por debajo de la cota en { $samples ->
        [one] su única muestra
       *[other] las { $samples } muestras
    }.
walkthrough-stability-above =
    V está por encima de la cota en { $outside } de { $samples ->
        [one] { $samples } muestra
       *[other] { $samples } muestras
    }, la primera en t = { $first } s; { $outsideSaturated } de ellas con la tensión saturada ({ $saturated ->
        [one] { $saturated } muestra saturada en total
       *[other] { $saturated } muestras saturadas en total
    }).
walkthrough-stability-cause-saturation = La mayoría de esas muestras tienen una tensión de mando más allá del límite: la saturación rompe la dinámica del error diseñada en la que se apoya la cota.
walkthrough-stability-cause-sampling = Con el observador perfecto y un modelo exacto, d̃2 = d̃4 = 0, y en tiempo continuo V se mantendría por debajo de la cota (sobre ella, con ganancias iguales). El lazo muestreado deja un error propio, del orden de Ts en las z_i: en el decaimiento, V se detiene en un suelo mientras la cota sigue bajando, de modo que V termina muy por encima de ella, y reducir Ts a la mitad multiplica el suelo por { $wt-decay-halfts }. Un error en la resistencia rotórica añade una perturbación propia, muy por encima de ese suelo: con la R_r del motor un 10 % por encima y por debajo de la del modelo, V termina el decaimiento en { $wt-decay-rrhigh } y { $wt-decay-rrlow } veces el suelo. Un error de inercia no la añade en el decaimiento: con la inercia del modelo un 20 % por encima y por debajo de la del motor (model.j = 0.024 y model.j = 0.016), V termina en { $wt-decay-jhigh } y { $wt-decay-jlow } veces el suelo.
walkthrough-stability-cause-estimation-errors = Los errores de estimación entran como d̃2 y d̃4; con los términos robustos desactivados, nada acota z2·d̃2 + z4·d̃4, así que la cota (que entonces supone d̃ = 0) no tiene por qué cumplirse.
walkthrough-stability-cause-eps-or-sampling = ε es demasiado pequeño para los d̃2, d̃4 reales, o el muestreo a 20 kHz añade un error que la demostración en tiempo continuo no tiene.

## The EKF's predictors compared (walkthrough-reports.js)

walkthrough-compare-note = Mismo escenario y misma semilla, solo cambia el predictor del EKF; cifras a partir de t = { $from } s, el final del transitorio de arranque, como en la franja de cifras.
walkthrough-compare-predictor = predictor
walkthrough-compare-tracking = RMS de seguimiento (rad/s)
walkthrough-compare-speed = RMS de la estimación de velocidad (rad/s)
walkthrough-compare-flux = RMS de la estimación de flujo (Wb)
walkthrough-compare-nis = NIS medio
walkthrough-compare-saturated = muestras en el límite de tensión
