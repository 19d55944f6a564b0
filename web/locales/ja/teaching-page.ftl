# 教材ツールのうち、レッスンと設計解説が読み込まれる前から表示される文言：詳細パネル、
# 各ステップの自作の制御則のエディタ（設計解説と設定の中）、設計解説自身の注記。

## 詳細パネル（inspect-panel.js）：一つのサンプルにおける設計のすべての項

inspect-title = サンプルの詳細：k = { $k }、t = { $time } s
inspect-copy = 厳密な値をコピー
inspect-copied = コピーしました
inspect-copy-failed = コピーできませんでした。代わりに表を選択してください
inspect-close = 閉じる（Esc）
inspect-exact = 厳密な値：{ $value }
inspect-group-step = ステップ{ $step }
inspect-group-voltage = 電圧 (54) と制限
inspect-group-estimate = 推定値 x̂ (k|k)
inspect-group-measured = 測定値と真値
inspect-term = 項
inspect-value = 値
inspect-unit = 単位
inspect-meaning = 意味
inspect-gain-caption = カルマンゲイン K_k（A⁻¹ × 状態の単位）と L = K_k/Ts（毎秒）
inspect-gain-row = 行

## 各ステップの自作の制御則（law-editor.js）

law-write = このステップを書く
law-names = 使える名前と関数
law-names-name = 名前
law-names-symbol = 記号
law-names-unit = 単位
law-names-meaning = 意味
law-names-functions = + − * / ^（または · と −）、括弧、数値、および関数 { $functions } が使えます。
law-error-at = { $at }文字目：{ $reason }
law-stale = 入力中の制御則ではありません。表示中の実行、この判定、残差のプロットは { $output } = { $law } によるものです。{ $verdict }
law-stale-after = 入力中の制御則ではありません。表示中の実行、この判定、残差のプロットは、{ $previous } = { $previousLaw } のもとでの { $output } = { $law } によるものです。{ $verdict }

## 設計解説（walkthrough.js）

